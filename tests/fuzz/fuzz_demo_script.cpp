// lagoon-demo's --script parser on any text.
#include "demo_options.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)lagoon::demo::parse_script(lagoon::fuzz::as_text(data, size), "fuzz.txt");
  return 0;
}
