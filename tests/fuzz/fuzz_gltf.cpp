// The glTF loader on both containers: byte 0 even makes the rest a .glb; odd makes it a .gltf whose JSON
// ends at the first NUL, followed by the bytes of its external buffer "m.bin". Limits are lowered so that a
// legal but huge model does not slow the search down; the loader must refuse past them, never allocate.
#include "fuzz_support.h"
#include "gltf/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view rest = lagoon::fuzz::as_text(data + 1, size - 1);
  lagoon::gltf::Limits limits;
  limits.max_vertices = 200'000;
  limits.max_indices = 600'000;
  limits.max_texture_size = 1024;
  limits.max_file_bytes = 4 << 20;
  std::filesystem::path path;
  if (data[0] % 2 == 0) {
    path = lagoon::fuzz::write_scratch("m.glb", rest);
  } else {
    const size_t nul = rest.find('\0');
    path = lagoon::fuzz::write_scratch("m.gltf", rest.substr(0, nul));
    lagoon::fuzz::write_scratch("m.bin",
                                nul == std::string_view::npos ? std::string_view() : rest.substr(nul + 1));
  }
  (void)lagoon::gltf::load_gltf(path, limits);
  return 0;
}
