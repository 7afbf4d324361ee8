// Lowers the calling thread's scheduling priority (nice 10, Linux). Work the physics hands to another thread
// ahead of time (the sea's next knot, the wake layers' next step) then gives way to the thread that steps
// the bodies: on a machine with two cores, three busy threads otherwise cost that thread whole time slices
// (the worst 60 Hz frame of `lagoon bench bodies`, docs/physics.md). Threads it starts inherit the priority.
#pragma once
#if defined(__linux__)
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace lagoon {

inline void lower_this_thread_priority() {
#if defined(__linux__)
  ::setpriority(PRIO_PROCESS, ::gettid(), 10);  // a thread's own nice value; failure only leaves it as it was
#endif
}

}  // namespace lagoon
