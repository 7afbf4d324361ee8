// Files from compute/optics/data embedded at build time (cmake/EmbedText.cmake).
#pragma once
#include <string_view>

namespace lagoon {

// The contents of the embedded file `name` (e.g. "cie1931_2deg_cmf_5nm.csv"); empty if there is none.
std::string_view embedded_text(std::string_view name);

}  // namespace lagoon
