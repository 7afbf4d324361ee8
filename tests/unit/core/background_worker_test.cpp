// BackgroundWorker (core/background_worker.h): jobs run in the order they were handed over, on one thread
// other than the caller's, soonest due first; their results and exceptions come back through the futures,
// and the worker does every queued job before it goes (its jobs read their owner, which must not go first).
// WorkerLane: owners sharing one worker, each waiting for its own jobs when it goes.
#include "core/background_worker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
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

// Holds a worker's thread until released (or 10 s, so a broken test fails instead of hanging).
struct Blocker {
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  void block(BackgroundWorker& worker) {
    std::promise<void> started;
    std::future<void> running = started.get_future();
    worker.post([&started, r = released] {
      started.set_value();
      r.wait_for(std::chrono::seconds(10));
    });
    running.wait();
  }
};

TEST(BackgroundWorker, TheSoonestDueJobGoesFirstAndEqualOnesInTheirOrder) {
  BackgroundWorker worker;
  Blocker blocker;
  blocker.block(worker);  // the rest queue up behind it
  std::vector<std::string> order;
  std::vector<std::future<void>> done;
  const std::pair<const char*, double> jobs[] = {{"3", 3.0},  {"never said", BackgroundWorker::kWhenever},
                                                 {"1a", 1.0}, {"2", 2.0},
                                                 {"1b", 1.0}, {"-5", -5.0}};
  for (const auto& [name, due] : jobs)
    done.push_back(worker.submit([&order, n = std::string(name)] { order.push_back(n); }, due));
  blocker.release.set_value();
  for (auto& d : done) d.get();
  EXPECT_EQ(order, (std::vector<std::string>{"-5", "1a", "1b", "2", "3", "never said"}));
}

TEST(BackgroundWorker, ALoopHelpsWithTheSoonestJobDueBeforeItsLimitOnItsOwnThread) {
  BackgroundWorker worker;
  Blocker blocker;
  blocker.block(worker);
  std::vector<std::thread::id> ran(3);
  std::vector<std::future<void>> done;
  for (int i = 0; i < 3; ++i)
    done.push_back(
        worker.submit([&ran, i] { ran[size_t(i)] = std::this_thread::get_id(); }, i == 0 ? 5.0 : 1.0 + i));
  EXPECT_FALSE(worker.help(2.0)) << "nothing is due before 2";
  EXPECT_TRUE(worker.help(2.5)) << "the job due at 2";
  EXPECT_EQ(ran[1], std::this_thread::get_id());
  EXPECT_EQ(done[1].wait_for(std::chrono::seconds(0)), std::future_status::ready);
  EXPECT_FALSE(worker.help(2.5)) << "the next is due at 3";
  blocker.release.set_value();
  for (auto& d : done) d.get();
  EXPECT_NE(ran[0], std::this_thread::get_id());
  EXPECT_NE(ran[2], std::this_thread::get_id());
}

TEST(WorkerLane, LanesShareOneThreadAndEachWaitsForItsOwnJobsWhenItGoes) {
  auto worker = std::make_shared<BackgroundWorker>();
  WorkerLane a(worker);
  std::atomic<bool> finished{false};
  std::thread::id b_ran;
  {
    WorkerLane b(worker);
    b.submit([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      b_ran = std::this_thread::get_id();
      finished = true;
    });  // the future dropped: only the lane waits
  }
  EXPECT_TRUE(finished.load()) << "the lane went before its job was done";
  EXPECT_EQ(a.submit([] { return std::this_thread::get_id(); }).get(), b_ran) << "one thread for both lanes";
  EXPECT_NE(b_ran, std::this_thread::get_id());
}

// A claim is taken once, whichever of many threads racing for it gets there first.
TEST(Claim, ExactlyOneOfManyRacingTakersTakesIt) {
  for (int round = 0; round < 50; ++round) {
    Claim claim;
    std::atomic<int> taken{0}, ready{0};
    std::vector<std::thread> takers;
    for (int t = 0; t < 6; ++t)
      takers.emplace_back([&] {
        ++ready;
        while (ready.load() < 6) std::this_thread::yield();
        if (claim.take()) ++taken;
      });
    for (std::thread& t : takers) t.join();
    EXPECT_EQ(taken.load(), 1) << "round " << round;
    EXPECT_FALSE(claim.take());
  }
}

}  // namespace
}  // namespace lagoon::test
