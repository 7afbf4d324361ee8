// The embedded-image decode path of the glTF loader (PNG and JPEG through stb_image, behind our signature
// and size checks), on raw bytes.
#include <span>

#include "gltf/image_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)lagoon::gltf::detail::decode_image(std::span(data, size), "fuzz input", 1024);
  return 0;
}
