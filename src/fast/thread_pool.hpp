// A fixed set of worker threads that run one job at a time over numbered work items, the
// calling thread joining in. Jobs allocate nothing; idle workers spin briefly, then sleep.
// It knows nothing about rendering and must not be shared by two drawing threads at once.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace shadelab::fast {

class ThreadPool {
 public:
  /// `threads` >= 1 counts the caller: threads - 1 workers are started.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return int(workers_.size()) + 1; }

  /// Calls fn(item, worker) for every item in [0, count), handing items out in order to
  /// whichever thread is free; worker is in [0, size()), 0 being the caller. Returns when all
  /// items are done. With one item, or one thread, everything runs on the caller.
  template <class Fn>
  void run(int count, Fn&& fn) {
    if (count <= 0) return;
    if (count == 1 || workers_.empty()) {
      for (int i = 0; i < count; ++i) fn(i, 0);
      return;
    }
    auto thunk = [](void* ctx, int item, int worker) { (*static_cast<Fn*>(ctx))(item, worker); };
    dispatch(count, thunk, &fn);
  }

 private:
  using Thunk = void (*)(void* ctx, int item, int worker);
  void dispatch(int count, Thunk thunk, void* ctx);
  void take_items(int worker);
  void worker_loop(int worker);

  std::vector<std::thread> workers_;
  std::atomic<std::uint32_t> generation_{0};
  std::atomic<int> next_item_{0};
  std::atomic<int> running_{0};  ///< workers still inside the current job
  std::atomic<bool> stop_{false};
  Thunk thunk_ = nullptr;
  void* ctx_ = nullptr;
  int count_ = 0;
};

/// Threads to use for a request of `threads`: itself when positive, else $SHADELAB_THREADS
/// when set to a positive number, else the number of cores.
int resolve_thread_count(int threads);

}  // namespace shadelab::fast
