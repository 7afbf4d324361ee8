#include "report_text.h"

#include <cstdio>

#include "io/atomic_file.h"

namespace lagoon::cli {

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

bool write_report_text(const std::filesystem::path& path, std::string_view text, const char* command) {
  if (Result<void> written = io::write_text_atomic(path, text); !written) {
    std::fprintf(stderr, "%s: %s\n", command, written.error().message.c_str());
    return false;
  }
  return true;
}

}  // namespace lagoon::cli
