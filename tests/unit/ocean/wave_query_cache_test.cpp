// WaveQuery's recent times and prefetch (ocean/wave_query.h): a time evaluated on another thread, or kept
// from before, answers exactly as a query that evaluates it afresh. The bodies' physics relies on this: its
// knots are prefetched, and a frame must not depend on how it was reached, nor on which thread got there
// first.
#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <memory>
#include <utility>
#include <vector>

#include "ocean/wave_query.h"

namespace lagoon::test {
namespace {

ocean::OceanParams small_sea() {
  ocean::OceanParams params;
  params.choppiness = 1.0;
  params.cascades = {{120.0, 64}, {20.0, 32}};
  return params;
}

std::vector<glm::dvec2> points() {
  std::vector<glm::dvec2> out;
  for (int i = 0; i < 40; ++i) out.push_back({-37.0 + 3.1 * i, 11.0 - 1.7 * i});
  return out;
}

// The same to the bit: both are the same arithmetic on the same inputs, whichever thread ran it.
void expect_same(const std::vector<ocean::WaveSample>& a, const std::vector<ocean::WaveSample>& b,
                 const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].height, b[i].height) << what << ", point " << i;
    EXPECT_EQ(a[i].normal, b[i].normal) << what << ", point " << i;
    EXPECT_EQ(a[i].velocity, b[i].velocity) << what << ", point " << i;
    EXPECT_EQ(a[i].error_bound_m, b[i].error_bound_m) << what << ", point " << i;
  }
}

TEST(WaveQueryCache, APrefetchedTimeAnswersAsAFreshQuery) {
  const std::vector<glm::dvec2> at = points();
  ocean::WaveQuery prefetching(small_sea());
  prefetching.prefetch(2.6);
  prefetching.sample(0.4, at);  // answered while 2.6 is evaluated on the other thread
  prefetching.prefetch(3.1);    // 2.6 not asked for yet: kept, and 3.1 started
  const auto prefetched = prefetching.sample(2.6, at);
  const auto next = prefetching.sample(3.1, at);
  ocean::WaveQuery fresh(small_sea());
  expect_same(prefetched, fresh.sample(2.6, at), "t = 2.6");
  expect_same(next, fresh.sample(3.1, at), "t = 3.1");
  // And the answers are of their own times (the waves move between them).
  EXPECT_NE(prefetched[0].height, next[0].height);
}

// heights_ahead: the heights of a time sampled on the query's worker, for a time being prefetched, one
// already evaluated and a new one, while the query answers other times; and for a model without a spectrum.
TEST(WaveQueryCache, HeightsSampledAheadAreTheHeightsSampledNow) {
  const std::vector<glm::dvec2> at = points();
  ocean::WaveQuery ahead(small_sea()), now(small_sea());
  ahead.sample(1.0, at);  // evaluated: among the recent times
  ahead.prefetch(2.6);
  auto prefetched = ahead.heights_ahead(2.6, at);
  auto recent = ahead.heights_ahead(1.0, at);
  auto fresh = ahead.heights_ahead(3.1, at);
  ahead.sample(0.4, at);  // the query goes on answering meanwhile
  for (auto [time, future] : {std::pair{2.6, &prefetched}, {1.0, &recent}, {3.1, &fresh}}) {
    const std::vector<double> got = future->heights.get();
    const std::vector<ocean::WaveSample> want = now.sample(time, at);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], want[i].height) << "t = " << time << ", " << i;
  }
  ocean::OceanParams waves = small_sea();
  waves.model = ocean::SurfaceModel::Gerstner;
  ocean::WaveQuery direct(waves), direct_now(waves);
  const std::vector<double> got = direct.heights_ahead(2.2, at).heights.get();
  const std::vector<ocean::WaveSample> want = direct_now.sample(2.2, at);
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], want[i].height) << "gerstner, " << i;
  EXPECT_NE(got[0], got[1]) << "the waves must be there";
}

TEST(WaveQueryCache, ATimeAskedAgainAnswersAsTheFirstTime) {
  const std::vector<glm::dvec2> at = points();
  ocean::WaveQuery query(small_sea());
  std::vector<std::vector<ocean::WaveSample>> first;
  const int times = int(ocean::WaveQuery::kRecentTimes) + 3;  // some fall out of the recent ones
  for (int k = 0; k < times; ++k) first.push_back(query.sample(0.2 * k, at));
  for (int k = times - 1; k >= 0; --k) expect_same(query.sample(0.2 * k, at), first[size_t(k)], "again");
}

TEST(WaveQueryCache, ALargeBatchSplitBetweenThreadsAnswersAsOnePointAtATime) {
  // 50,000 points are split between the query's two threads; each answer is the one a single point gets,
  // wherever the split falls (the chunks' ends included).
  std::vector<glm::dvec2> at;
  for (int i = 0; i < 50000; ++i) at.push_back({-90.0 + 0.0037 * i, 40.0 - 0.0021 * i});
  ocean::WaveQuery query(small_sea());
  const std::vector<ocean::WaveSample> batch = query.sample(1.7, at);
  std::vector<ocean::WaveSample> one_by_one;
  for (size_t i :
       {size_t(0), size_t(1), size_t(24999), size_t(25000), size_t(25001), size_t(37777), size_t(49999)})
    EXPECT_EQ(batch[i].height, query.sample(1.7, at[i].x, at[i].y).height) << "point " << i;
  for (int i = 0; i < 50000; i += 997)
    one_by_one.push_back(query.sample(1.7, at[size_t(i)].x, at[size_t(i)].y));
  std::vector<ocean::WaveSample> strided;
  for (int i = 0; i < 50000; i += 997) strided.push_back(batch[size_t(i)]);
  expect_same(strided, one_by_one, "batch against single points");
}

// In a catch-up the caller runs ahead of the worker (on two cores it shares with the wake layers): a time
// prefetched but not begun is evaluated by whoever needs it first, here the caller, without waiting for the
// worker, and later prefetches do not wait for the earlier ones. The answers are still a fresh query's.
TEST(WaveQueryCache, ACallerThatOvertakesTheWorkerEvaluatesThePrefetchedTimeItself) {
  const std::vector<glm::dvec2> at = points();
  auto worker = std::make_shared<BackgroundWorker>();
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::promise<void> started;
  worker->post([&started, released] {
    started.set_value();
    released.wait_for(std::chrono::seconds(10));  // a broken query fails the test rather than hanging it
  });
  started.get_future().wait();
  ocean::WaveQueryOptions options;
  options.worker = worker;
  ocean::WaveQuery query(small_sea(), {}, options);
  query.prefetch(2.6, 1.0);
  query.prefetch(3.1, 2.0);  // does not wait for 2.6, which nobody has begun
  auto ahead = query.heights_ahead(3.1, at, 2.0);
  EXPECT_FALSE(query.ready(2.6));
  const auto blocked_until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  const auto got = query.sample(2.6, at);
  const auto next = query.sample(3.1, at);
  EXPECT_LT(std::chrono::steady_clock::now(), blocked_until) << "the caller waited for the held worker";
  EXPECT_EQ(released.wait_for(std::chrono::seconds(0)), std::future_status::timeout);
  EXPECT_TRUE(ahead.claim()) << "the worker is held: the caller may sample the knot itself";
  release.set_value();
  ocean::WaveQuery fresh(small_sea());
  expect_same(got, fresh.sample(2.6, at), "t = 2.6");
  expect_same(next, fresh.sample(3.1, at), "t = 3.1");
  EXPECT_TRUE(ahead.heights.get().empty()) << "claimed by the caller: the worker's job gives nothing";
}

}  // namespace
}  // namespace lagoon::test
