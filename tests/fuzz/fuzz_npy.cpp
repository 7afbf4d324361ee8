// The .npy reader on any bytes; whatever it accepts must write back and read again to the same array.
#include <cstdlib>
#include <cstring>

#include "fuzz_support.h"
#include "io/npy.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = lagoon::fuzz::write_scratch("in.npy", lagoon::fuzz::as_text(data, size));
  auto array = lagoon::io::read_npy(path);
  if (!array) return 0;
  const auto copy = lagoon::fuzz::scratch() / "out.npy";
  if (!lagoon::io::write_npy(copy, array->data, array->shape)) std::abort();
  auto back = lagoon::io::read_npy(copy);
  if (!back || back->shape != array->shape || back->data.size() != array->data.size()) std::abort();
  if (!array->data.empty() &&  // an empty vector's data() may be null, which memcmp must not see
      std::memcmp(back->data.data(), array->data.data(), array->data.size() * sizeof(float)) != 0)
    std::abort();  // bit-exact: NaN payloads included
  return 0;
}
