// A command started through /bin/sh without waiting for it: for tests that signal a running process or
// measure its peak memory. stdout and stderr go to a log file the test can poll.
#pragma once
#include <sys/types.h>

#include <string>

namespace lagoon::test {

class ChildProcess {
 public:
  explicit ChildProcess(const std::string& command_line);
  ~ChildProcess();  // kills and reaps a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  std::string output() const;  // what it has printed so far
  // Polls the output until it contains `needle`; false after `timeout_s` or when the child has exited.
  bool wait_for_output(const std::string& needle, double timeout_s);
  void send(int signal);

  struct Exit {
    int code = -1;         // exit status, or 128 + signal when killed by one
    long max_rss_kib = 0;  // peak resident memory of the child (wait4's ru_maxrss)
  };
  Exit wait();

 private:
  pid_t pid_ = -1;
  std::string log_;
};

}  // namespace lagoon::test
