// Exit codes of every Lagoon executable (the CLI and the demo).
#pragma once

namespace lagoon::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // missing/unreadable/invalid file, no device, Vulkan error
inline constexpr int kExitUsage = 2;       // bad command line
inline constexpr int kExitValidation = 3;  // LAGOON_VALIDATION=1 and the validation layer reported errors

}  // namespace lagoon::cli
