# Warnings as errors on our own code only (third-party headers are included as SYSTEM).
# -Wno-restrict: GCC 12 reports false positives inside std::string::operator+ at -O2/-O3 (GCC bug 105329).
add_library(lagoon_warnings INTERFACE)
target_compile_options(lagoon_warnings INTERFACE -Wall -Wextra -Werror -Wno-missing-field-initializers
                       $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
