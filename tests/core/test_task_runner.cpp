// The task runners: the inline runner's FIFO order under the test's control, and the thread
// pool running everything posted and shutting down deterministically.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>
#include <vector>

#include "core/thread_pool_runner.hpp"
#include "tests/support/inline_runner.hpp"

namespace globe::core {
namespace {

TEST(InlineRunner, RunsNothingUntilAskedThenInPostingOrder) {
  globe::testing::InlineRunner runner;
  std::vector<int> ran;
  for (int i = 0; i < 3; ++i) runner.post([&ran, i] { ran.push_back(i); });
  EXPECT_TRUE(ran.empty());
  EXPECT_EQ(runner.queued(), 3U);
  EXPECT_TRUE(runner.runOne());
  EXPECT_EQ(ran, std::vector<int>{0});
  // A task may post another: runAll runs it too, after those already queued.
  runner.post([&] { runner.post([&ran] { ran.push_back(9); }); });
  EXPECT_EQ(runner.runAll(), 4U);
  EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 9}));
  EXPECT_FALSE(runner.runOne());
}

TEST(ThreadPoolRunner, RunsEveryPostedTask) {
  std::atomic<int> count{0};
  {
    ThreadPoolRunner pool(2);
    EXPECT_EQ(pool.threadCount(), 2U);
    std::promise<void> allRan;
    for (int i = 0; i < 1000; ++i) {
      pool.post([&] {
        if (++count == 1000) allRan.set_value();
      });
    }
    ASSERT_EQ(allRan.get_future().wait_for(std::chrono::seconds(60)), std::future_status::ready)
        << count << " of 1000 tasks ran within 60 s";
  }
  EXPECT_EQ(count, 1000);
  EXPECT_EQ(ThreadPoolRunner(0).threadCount(), 1U);
}

TEST(ThreadPoolRunner, ShutdownDropsQueuedTasksFinishesRunningOnesAndJoins) {
  ThreadPoolRunner pool(1);
  std::promise<void> started, release;
  std::atomic<bool> blockerFinished{false};
  std::atomic<int> queuedRan{0};
  pool.post([&] {
    started.set_value();
    release.get_future().wait();
    blockerFinished = true;
  });
  started.get_future().wait();  // the only worker is now busy
  for (int i = 0; i < 5; ++i) pool.post([&] { ++queuedRan; });
  EXPECT_EQ(pool.queued(), 5U);

  auto dropped = std::async(std::launch::async, [&] { return pool.shutdown(); });
  // shutdown() empties the queue before it joins; only then is the running task let go.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (pool.queued() != 0) {
    ASSERT_TRUE(std::chrono::steady_clock::now() < deadline) << "shutdown never took the queue";
    std::this_thread::yield();
  }
  release.set_value();
  EXPECT_EQ(dropped.get(), 5U);
  EXPECT_TRUE(blockerFinished);
  EXPECT_EQ(queuedRan, 0);

  pool.post([&] { ++queuedRan; });  // after shutdown: dropped
  EXPECT_EQ(pool.queued(), 0U);
  EXPECT_EQ(pool.shutdown(), 0U);
  EXPECT_EQ(queuedRan, 0);
}

}  // namespace
}  // namespace globe::core
