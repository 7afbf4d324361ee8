// BackgroundWorker (core/background_worker.h): jobs run in the order they were handed over, on one thread
// other than the caller's, their results and exceptions come back through the futures, and the worker does
// every queued job before it goes (its jobs read their owner, which must not go first).
#include "core/background_worker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

namespace lagoon::test {
namespace {

TEST(BackgroundWorker, JobsRunInOrderOnOneOtherThread) {
  BackgroundWorker worker;
  std::vector<int> order;  // written by the worker's jobs only, read after the last one's future
  std::vector<std::future<std::thread::id>> ran;
  for (int i = 0; i < 20; ++i)
    ran.push_back(worker.submit([&order, i] {
      order.push_back(i);
      return std::this_thread::get_id();
    }));
  std::vector<std::thread::id> threads;
  for (auto& r : ran) threads.push_back(r.get());
  for (const std::thread::id& id : threads) EXPECT_EQ(id, threads.front());
  EXPECT_NE(threads.front(), std::this_thread::get_id());
  std::vector<int> expected(20);
  for (int i = 0; i < 20; ++i) expected[size_t(i)] = i;
  EXPECT_EQ(order, expected);
}

TEST(BackgroundWorker, ResultsAndExceptionsComeBackThroughTheFutures) {
  BackgroundWorker worker;
  auto sum = worker.submit([] { return 2 + 3; });
  auto failed = worker.submit([]() -> int { throw std::runtime_error("no knot"); });
  EXPECT_EQ(sum.get(), 5);
  EXPECT_THROW(failed.get(), std::runtime_error);
  EXPECT_EQ(worker.submit([] { return 7; }).get(), 7) << "a job that threw does not stop the worker";
}

TEST(BackgroundWorker, QueuedJobsAreDoneBeforeItGoesAndDroppedFuturesDoNotWait) {
  std::atomic<int> done{0};
  {
    BackgroundWorker worker;
    worker.submit([] { std::this_thread::sleep_for(std::chrono::milliseconds(50)); });  // dropped at once
    for (int i = 0; i < 30; ++i) worker.submit([&done] { ++done; });
    EXPECT_LT(done.load(), 30) << "the first job still sleeps: submit must not have waited for it";
  }
  EXPECT_EQ(done.load(), 30);
}

}  // namespace
}  // namespace lagoon::test
