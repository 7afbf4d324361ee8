#include "support/child_process.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace lagoon::test {
namespace {
std::atomic<int> g_counter{0};
}

ChildProcess::ChildProcess(const std::string& command_line) {
  log_ = (std::filesystem::temp_directory_path() /
          ("lagoon-child-" + std::to_string(::getpid()) + "-" + std::to_string(g_counter++) + ".log"))
             .string();
  const std::string script = "exec " + command_line + " >'" + log_ + "' 2>&1";
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    ::execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  std::error_code ec;
  std::filesystem::remove(log_, ec);
}

std::string ChildProcess::output() const {
  std::ifstream in(log_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool ChildProcess::wait_for_output(const std::string& needle, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    if (output().find(needle) != std::string::npos) return true;
    if (pid_ <= 0) return false;
    siginfo_t info{};  // peek without reaping: wait() still reads the exit status and the peak memory
    if (::waitid(P_PID, id_t(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_)
      return output().find(needle) != std::string::npos;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

void ChildProcess::send(int signal) {
  if (pid_ > 0) ::kill(pid_, signal);
}

ChildProcess::Exit ChildProcess::wait() {
  Exit exit;
  if (pid_ <= 0) return exit;
  int status = 0;
  struct rusage usage {};
  if (::wait4(pid_, &status, 0, &usage) == pid_) {
    exit.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    exit.max_rss_kib = usage.ru_maxrss;
  }
  pid_ = -1;
  return exit;
}

}  // namespace lagoon::test
