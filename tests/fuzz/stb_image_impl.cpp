// stb_image's implementation, compiled into the fuzz targets from Debian's header. Debian's libstb is built
// without instrumentation, so without this the fuzzer would get no coverage from the decoder and ASan would
// not see an overflow inside it. These definitions come before libstb on the link line, so they are the ones
// used.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
