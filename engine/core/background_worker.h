// One thread that works ahead for a loop, in the order the loop hands it jobs (the bodies' next knot of the
// sea and its points, their wake layers' next step: issue 35). A thread per job (std::async) cost the loop
// a stall of several milliseconds whenever the cores were busy: each new thread was scheduled onto the
// loop's core. This one is made once. It keeps the normal priority: a lower one starved the helpers, and the
// loop waiting on them, whenever other processes kept the cores busy (docs/physics.md, "Off the step").
#pragma once
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>

namespace lagoon {

class BackgroundWorker {
 public:
  BackgroundWorker() : thread_([this] { run(); }) {}
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;
  // Does the jobs still queued, then joins: they may read their owner, which outlives this.
  ~BackgroundWorker() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  // Queues `job`; the future gives its result (or rethrows what it threw). Dropping the future does not wait.
  template <typename F>
  std::future<std::invoke_result_t<F>> submit(F job) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F>()>>(std::move(job));
    std::future<std::invoke_result_t<F>> result = task->get_future();
    {
      std::lock_guard lock(mutex_);
      jobs_.push_back([task] { (*task)(); });
    }
    wake_.notify_one();
    return result;
  }

 private:
  void run() {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // stopping, and nothing left
        job = std::move(jobs_.front());
        jobs_.pop_front();
      }
      job();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once the rest is made
};

}  // namespace lagoon
