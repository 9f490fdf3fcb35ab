// The fast pipeline's thread pool: every item of a job runs once, on a thread of the pool,
// whatever the thread count and however the threads take each other's shares; a job started
// in the background runs while the caller goes on, and the caller takes its remaining items
// when it waits for it.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "fast/thread_pool.hpp"

namespace shadelab::fast {
namespace {

TEST(ThreadPool, RunsEveryItemOnceOnAThreadOfThePool) {
  for (int threads = 1; threads <= 5; ++threads) {
    ThreadPool pool(threads);
    for (int count : {0, 1, 2, 3, 7, 64, 1000}) {
      std::vector<std::atomic<int>> runs(std::size_t(count) + 1);
      std::atomic<bool> bad_worker{false};
      pool.run(count, [&](int item, int worker) {
        runs[std::size_t(item)].fetch_add(1);
        if (worker < 0 || worker >= threads) bad_worker = true;
        if (item % 5 == 0) std::this_thread::yield();  // uneven items: shares are taken over
      });
      for (int i = 0; i < count; ++i) ASSERT_EQ(runs[std::size_t(i)].load(), 1) << threads << " threads, item " << i << " of " << count;
      EXPECT_EQ(runs[std::size_t(count)].load(), 0);
      EXPECT_FALSE(bad_worker.load());
    }
  }
}

// Jobs back to back, each its own function: every item runs that job's function, and what an
// item writes (plain writes) is there when the job returns. A thread that took the next job's
// items with the last one's function, or a job that ended before its items, shows here.
TEST(ThreadPool, BackToBackJobsRunTheirOwnFunctions) {
  for (int threads : {2, 3}) {
    ThreadPool pool(threads);
    for (int job = 0; job < 3000; ++job) {
      const int count = 1 + job % 37;
      std::vector<int> written(std::size_t(count), -1);
      pool.run(count, [&written, job](int item, int) { written[std::size_t(item)] = job * 64 + item; });
      for (int i = 0; i < count; ++i) {
        ASSERT_EQ(written[std::size_t(i)], job * 64 + i) << threads << " threads, job " << job << ", item " << i;
      }
    }
  }
}

// Thread w's share is items [count w / threads, count (w + 1) / threads), taken from the
// front: with every thread held at its first item until all have one, each thread's first
// item is the first of its share.
TEST(ThreadPool, EachThreadStartsWithItsOwnShare) {
  const int threads = 3, count = 9;
  ThreadPool pool(threads);
  std::vector<int> first(threads, -1);
  std::atomic<int> arrived{0};
  pool.run(count, [&](int item, int worker) {
    if (first[std::size_t(worker)] >= 0) return;
    first[std::size_t(worker)] = item;
    arrived.fetch_add(1);
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (arrived.load() < threads && std::chrono::steady_clock::now() < until) std::this_thread::yield();
  });
  EXPECT_EQ(first, (std::vector<int>{0, 3, 6}));
}

TEST(ThreadPool, StartRunsInTheBackgroundAndWaitJoinsIn) {
  ThreadPool one(1);
  int calls = 0;
  auto count_calls = [&](int) { ++calls; };
  EXPECT_FALSE(one.start(4, count_calls));  // no worker: nothing started
  one.wait();
  EXPECT_EQ(calls, 0);

  ThreadPool pool(2);
  // Item 0 (the worker's first) holds its thread until item 1 has run: only the caller,
  // taking the rest of the job at wait(), can run it.
  std::atomic<bool> second_done{false};
  std::atomic<bool> timed_out{false};
  auto job = [&](int item) {
    if (item == 1) {
      second_done = true;
      return;
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!second_done.load()) {
      if (std::chrono::steady_clock::now() > until) {
        timed_out = true;
        return;
      }
      std::this_thread::yield();
    }
  };
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> second_on_caller{false};
  auto wrapped = [&](int item) {
    if (item == 1) second_on_caller = std::this_thread::get_id() == caller;
    job(item);
  };
  ASSERT_TRUE(pool.start(2, wrapped));
  pool.wait();
  EXPECT_FALSE(timed_out.load());
  EXPECT_TRUE(second_done.load());
  EXPECT_TRUE(second_on_caller.load());

  // run() waits for a job started before it; the background job's items all run once.
  std::vector<std::atomic<int>> runs(500);
  auto each = [&](int item) {
    runs[std::size_t(item)].fetch_add(1);
  };
  ASSERT_TRUE(pool.start(500, each));
  std::atomic<int> later{0};
  pool.run(10, [&](int, int) { later.fetch_add(1); });
  for (int i = 0; i < 500; ++i) ASSERT_EQ(runs[std::size_t(i)].load(), 1) << i;
  EXPECT_EQ(later.load(), 10);
}

}  // namespace
}  // namespace shadelab::fast
