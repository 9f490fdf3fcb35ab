// The fast pipeline's thread pool: a generation counter wakes the workers for each job, items
// are claimed with an atomic counter, and the caller waits until every worker has left the job.
#include "fast/thread_pool.hpp"

#include <chrono>
#include <cstdlib>

namespace shadelab::fast {

namespace {

// How long an idle worker keeps polling before it sleeps: long enough to span the gap
// between the stages of one draw and between draws of a frame, short enough not to burn a
// core when nothing is drawn. A GL program's glBegin/glEnd calls between two draws take the
// calling thread about half a millisecond for the teapot's 19,200 vertices; a worker that
// slept after 300 us then had to be woken through the kernel (in a VM, tens of
// microseconds): 1 ms took the teapot's median frame from 3.45 to 3.21 ms on two threads. At
// most 1 ms of one core per frame is spent polling.
constexpr auto kSpin = std::chrono::microseconds(1000);

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

int resolve_thread_count(int threads) {
  if (threads > 0) return threads;
  if (const char* env = std::getenv("SHADELAB_THREADS")) {
    int n = std::atoi(env);
    if (n > 0) return n;
  }
  unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? int(cores) : 1;
}

ThreadPool::ThreadPool(int threads) {
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { worker_loop(w); });
}

ThreadPool::~ThreadPool() {
  stop_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ThreadPool::dispatch(int count, Thunk thunk, void* ctx) {
  thunk_ = thunk;
  ctx_ = ctx;
  count_ = count;
  next_item_.store(0, std::memory_order_relaxed);
  running_.store(int(workers_.size()));
  generation_.fetch_add(1);  // publishes the job (sequentially consistent)
  generation_.notify_all();
  take_items(0);
  while (running_.load() != 0) cpu_relax();
}

void ThreadPool::take_items(int worker) {
  for (int i = next_item_.fetch_add(1); i < count_; i = next_item_.fetch_add(1)) {
    thunk_(ctx_, i, worker);
  }
}

void ThreadPool::worker_loop(int worker) {
  std::uint32_t seen = 0;
  while (true) {
    auto start = std::chrono::steady_clock::now();
    int polls = 0;
    while (generation_.load() == seen) {
      cpu_relax();
      if (++polls % 256 == 0 && std::chrono::steady_clock::now() - start > kSpin) {
        generation_.wait(seen);
      }
    }
    seen = generation_.load();
    if (stop_.load()) return;
    take_items(worker);
    running_.fetch_sub(1);
  }
}

}  // namespace shadelab::fast
