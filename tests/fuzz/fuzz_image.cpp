// The image decode path of the glTF loader and of the PNG reader (PNG, JPEG and WebP through libpng,
// libjpeg-turbo and libwebp, behind the signature and size checks), on raw bytes.
#include <span>

#include "gltf/image_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)lagoon::gltf::detail::decode_image(std::span(data, size), "fuzz input", 1024);
  return 0;
}
