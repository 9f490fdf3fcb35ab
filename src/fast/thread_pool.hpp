// A fixed set of worker threads that run one job at a time over numbered work items, the
// calling thread joining in. Each thread owns a contiguous share of a job's items and takes
// them from the front; a thread done with its share takes from the back of another's. A job
// ends when its items are done, whoever did them: a worker the system has not run yet (a
// machine shared with other work) holds nothing up, and finds nothing left when it runs.
// Jobs allocate nothing; idle workers spin briefly, then sleep.
// It knows nothing about rendering and must not be shared by two drawing threads at once.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
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

  /// Calls fn(item, worker) for every item in [0, count); worker is in [0, size()), 0 being
  /// the caller. Thread w owns items [count w / size(), count (w + 1) / size()) and runs them
  /// in order, unless a thread done with its own takes them from the back first: jobs split
  /// alike (consecutive stages over the same data) mostly find on each thread what that
  /// thread made in the stage before, in its cache, and threads work far apart. Returns when
  /// all items are done. With one item, or one thread, everything runs on the caller in order.
  template <class Fn>
  void run(int count, Fn&& fn) {
    wait();
    if (count <= 0) return;
    if (count == 1 || workers_.empty()) {
      for (int i = 0; i < count; ++i) fn(i, 0);
      return;
    }
    auto thunk = [](void* ctx, int item, int worker) { (*static_cast<Fn*>(ctx))(item, worker); };
    dispatch(count, thunk, &fn);
  }

  /// Starts fn(item) for every item in [0, count) on the workers and returns at once, while
  /// they run; false, with nothing started, when there are no workers. The caller joins in
  /// at wait(), taking the items not yet taken. `fn` must live until the job has ended: wait()
  /// waits for that, and so does every run() and start() first.
  template <class Fn>
  bool start(int count, Fn& fn) {
    wait();
    if (workers_.empty() || count <= 0) return false;
    auto thunk = [](void* ctx, int item, int) { (*static_cast<Fn*>(ctx))(item); };
    publish(count, thunk, &fn, false);
    return true;
  }

  /// Returns when the job started by start(), if any, has ended (at once when none runs),
  /// taking items of it that no worker has taken yet.
  void wait() {
    if (pending_.load(std::memory_order_acquire) == 0) return;
    take_items(0);
    finish();
  }

 private:
  using Thunk = void (*)(void* ctx, int item, int worker);
  static void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  /// Hands out a job's items: over every thread's share, or with `caller_joins` false over
  /// the workers' only; wakes the workers.
  void publish(int count, Thunk thunk, void* ctx, bool caller_joins);
  void dispatch(int count, Thunk thunk, void* ctx);
  void take_items(int worker);
  /// Waits until every item of the current job is done (items other threads took and still
  /// run); yields the processor while it waits long, to a worker that may need it.
  void finish();
  void worker_loop(int worker);

  /// A thread's share of the current job: the next item to take from the front (low 32
  /// bits) and the end (high 32 bits); empty when they meet. On its own cache line.
  struct alignas(64) Share {
    std::atomic<std::uint64_t> range{0};
  };

  std::vector<std::thread> workers_;
  std::unique_ptr<Share[]> shares_;
  std::atomic<std::uint32_t> generation_{0};
  std::atomic<int> pending_{0};  ///< items of the current job not yet done
  std::atomic<bool> stop_{false};
  // The current job's function. Set before its items are published and read by a thread only
  // after it has claimed an item: the job is then still running, so they are that job's.
  std::atomic<Thunk> thunk_{nullptr};
  std::atomic<void*> ctx_{nullptr};
};

/// Threads to use for a request of `threads`: itself when positive, else $SHADELAB_THREADS
/// when set to a positive number, else the number of cores.
int resolve_thread_count(int threads);

}  // namespace shadelab::fast
