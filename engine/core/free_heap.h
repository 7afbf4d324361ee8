// Hands the heap's free memory back to the system. Shader compilation (lavapipe JIT-compiles a pipeline at
// its first dispatch) and rebuilt renderers free tens of MiB that the allocator keeps resident otherwise:
// the resident set then stays at its high-water mark, and later allocations, a leak among them, fill the
// freed memory without showing. Long-running loops call this now and then (docs/reliability.md).
#pragma once
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lagoon {

inline void release_free_heap() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

}  // namespace lagoon
