// One thread that works ahead for a loop (the bodies' next knot of the sea and its points, their wake
// layers' next step: issue 35). A thread per job (std::async) cost the loop a stall of several milliseconds
// whenever the cores were busy: each new thread was scheduled onto the loop's core. This one is made once.
// It keeps the normal priority: a lower one starved the helpers, and the loop waiting on them, whenever
// other processes kept the cores busy (docs/physics.md, "Off the step").
//
// Several owners may share one worker (WorkerLane): the bodies' sea and their wake layers do, so that their
// helpers never take both cores of a two-core machine from the loop. A job may say when the loop will need
// it (`due`, in the loop's own clock); the worker takes the soonest first, and jobs due at the same time (or
// never said) in the order they came.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>

namespace lagoon {

class BackgroundWorker {
 public:
  static constexpr double kWhenever = std::numeric_limits<double>::infinity();

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
  std::future<std::invoke_result_t<F>> submit(F job, double due = kWhenever) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F>()>>(std::move(job));
    std::future<std::invoke_result_t<F>> result = task->get_future();
    post([task] { (*task)(); }, due);
    return result;
  }

  // Runs the soonest queued job on the calling thread if it is due before `due_before`; false when none is.
  // A loop that has overtaken its worker (a catch-up) takes one piece of the work it will soon need at a
  // step, instead of waiting for all of it at once when it needs it.
  bool help(double due_before) {
    std::function<void()> job;
    {
      std::lock_guard lock(mutex_);
      if (jobs_.empty() || !(jobs_.begin()->first.first < due_before)) return false;
      job = std::move(jobs_.begin()->second);
      jobs_.erase(jobs_.begin());
    }
    job();
    return true;
  }

  // Queues a job that must not throw (submit()'s packaged tasks do not).
  void post(std::function<void()> job, double due = kWhenever) {
    {
      std::lock_guard lock(mutex_);
      jobs_.emplace(std::pair(due, next_++), std::move(job));
    }
    wake_.notify_one();
  }

 private:
  void run() {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // stopping, and nothing left
        auto first = jobs_.begin();
        job = std::move(first->second);
        jobs_.erase(first);
      }
      job();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::pair<double, uint64_t>, std::function<void()>> jobs_;  // by (due, arrival)
  uint64_t next_ = 0;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once the rest is made
};

// Work done once, by whichever thread begins it first: the worker's job, or a caller that needs it before
// the worker has reached it (a catch-up that overtook the worker), which then does it itself instead of
// waiting behind the worker's other jobs. take() is true for exactly one taker; a job that finds the work
// taken returns at once, and a caller that finds it taken waits for the job's future.
class Claim {
 public:
  bool take() { return !taken_.exchange(true); }

 private:
  std::atomic<bool> taken_{false};
};

// One owner's jobs on a worker it may share with others (its own when none is given). Destroying the lane
// waits for the jobs it handed over: they read their owner, which holds the lane as its last member.
class WorkerLane {
 public:
  explicit WorkerLane(std::shared_ptr<BackgroundWorker> worker = nullptr)
      : worker_(worker ? std::move(worker) : std::make_shared<BackgroundWorker>()) {}
  WorkerLane(const WorkerLane&) = delete;
  WorkerLane& operator=(const WorkerLane&) = delete;
  ~WorkerLane() {
    std::unique_lock lock(count_->mutex);
    count_->done.wait(lock, [this] { return count_->queued == 0; });
  }

  template <typename F>
  std::future<std::invoke_result_t<F>> submit(F job, double due = BackgroundWorker::kWhenever) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F>()>>(std::move(job));
    std::future<std::invoke_result_t<F>> result = task->get_future();
    {
      std::lock_guard lock(count_->mutex);
      ++count_->queued;
    }
    worker_->post(
        [task, count = count_] {
          (*task)();
          std::lock_guard lock(count->mutex);
          --count->queued;
          count->done.notify_all();
        },
        due);
    return result;
  }

 private:
  struct Count {
    std::mutex mutex;
    std::condition_variable done;
    int queued = 0;
  };
  std::shared_ptr<BackgroundWorker> worker_;
  std::shared_ptr<Count> count_ = std::make_shared<Count>();  // outlives the lane while a job finishes
};

}  // namespace lagoon
