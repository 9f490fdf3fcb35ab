// The lab's render queue (apps/shadelab/render_queue.hpp): clients served in turn, each
// client's renders in order, the bounds refused at once.
#include "render_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace shadelab::cli {
namespace {

// Blocks the queue's only worker until released, so that the jobs queued meanwhile wait.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = false;
  void wait() {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return open; });
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(m);
      open = true;
    }
    cv.notify_all();
  }
};

TEST(RenderQueue, ClientsAreServedInTurnEachInOrder) {
  RenderQueue q(1, 100, 100);
  Gate gate;
  std::atomic<bool> holding{false};
  std::thread blocker([&] { q.run("blocker", [&] { holding = true; gate.wait(); }); });
  while (!holding) std::this_thread::yield();

  // Client a queues three renders, then b two, then c one, one thread each, in that order.
  std::mutex m;
  std::vector<std::string> order;
  std::vector<std::thread> clients;
  auto submit = [&](const std::string& client, int i) {
    clients.emplace_back([&, client, i] {
      EXPECT_TRUE(q.run(client, [&, client, i] {
        std::lock_guard<std::mutex> lock(m);
        order.push_back(client + std::to_string(i));
      }));
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // queued before the next
  };
  submit("a", 1), submit("a", 2), submit("a", 3), submit("b", 1), submit("b", 2), submit("c", 1);
  gate.release();
  blocker.join();
  for (std::thread& t : clients) t.join();
  EXPECT_EQ(order, (std::vector<std::string>{"a1", "b1", "c1", "a2", "b2", "a3"}));
}

TEST(RenderQueue, AFullQueueOrAClientsFullShareIsRefusedAtOnce) {
  RenderQueue q(1, 4, 2);
  Gate gate;
  std::atomic<int> started{0};
  std::vector<std::thread> held;
  // a holds its two, b two more: the queue is full (one running, three waiting).
  for (const char* client : {"a", "a", "b", "b"}) {
    held.emplace_back([&, client] { EXPECT_TRUE(q.run(client, [&] { ++started; gate.wait(); })); });
  }
  while (started == 0) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(q.run("c", [] { ADD_FAILURE() << "ran in a full queue"; }));
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(1));
  gate.release();
  for (std::thread& t : held) t.join();
  EXPECT_EQ(started.load(), 4);

  RenderQueue r(1, 10, 2);
  Gate gate2;
  std::atomic<int> started2{0};
  std::vector<std::thread> two;
  for (int i = 0; i < 2; ++i) two.emplace_back([&] { EXPECT_TRUE(r.run("a", [&] { ++started2; gate2.wait(); })); });
  while (started2 == 0) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(r.run("a", [] { ADD_FAILURE() << "a third render of one client ran"; }));
  std::atomic<bool> other{false};
  std::thread b([&] { EXPECT_TRUE(r.run("b", [&] { other = true; })); });  // another client still fits
  gate2.release();
  for (std::thread& t : two) t.join();
  b.join();
  EXPECT_TRUE(other.load());
}

TEST(RenderQueue, AJobsExceptionLeavesTheWorkerServing) {
  RenderQueue q(1, 4, 4);
  EXPECT_TRUE(q.run("a", [] { throw std::runtime_error("render failed"); }));
  bool ran = false;
  EXPECT_TRUE(q.run("a", [&] { ran = true; }));
  EXPECT_TRUE(ran);
}

}  // namespace
}  // namespace shadelab::cli
