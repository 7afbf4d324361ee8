// Copies what is written to the process's stderr (file descriptor 2) while it lives, and still writes it
// there: lagoon.run() shows a command's progress as the `lagoon` executable does, and raises its error
// message. A pipe and a reader thread, so a long command's output is neither delayed nor unbounded in the
// pipe.
#pragma once
#include <mutex>
#include <string>
#include <thread>

namespace lagoon::python {

class StderrTee {
 public:
  StderrTee();
  ~StderrTee();
  StderrTee(const StderrTee&) = delete;
  StderrTee& operator=(const StderrTee&) = delete;

  // Stops copying (restores stderr) and returns what was written; the last 64 KiB of it.
  std::string finish();

 private:
  int saved_ = -1;  // the original stderr
  int read_ = -1, write_ = -1;
  std::thread reader_;
  std::mutex mutex_;
  std::string text_;
  bool finished_ = false;
};

}  // namespace lagoon::python
