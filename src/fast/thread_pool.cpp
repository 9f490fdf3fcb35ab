// The fast pipeline's thread pool: a generation counter wakes the workers for each job, items
// are claimed from per-thread shares by compare-and-swap, and the caller waits until every
// item is done. It never waits for a worker to arrive: on a machine whose cores run other
// work too, a worker may not run for a whole scheduling slice (milliseconds), and a pool that
// waited for every worker to check in and out of every job took up to 16 times as long as
// one thread on programs of many small draws.
#include "fast/thread_pool.hpp"

#include <algorithm>
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

ThreadPool::ThreadPool(int threads) : shares_(std::make_unique<Share[]>(std::size_t(std::max(threads, 1)))) {
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { worker_loop(w); });
}

ThreadPool::~ThreadPool() {
  wait();
  stop_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  for (std::thread& t : workers_) t.join();
}

// The previous job is done (every share empty, nothing pending): the job's function and its
// item count are set first, then its shares filled, each store releasing them to whoever
// claims from it.
void ThreadPool::publish(int count, Thunk thunk, void* ctx, bool caller_joins) {
  thunk_.store(thunk, std::memory_order_relaxed);
  ctx_.store(ctx, std::memory_order_relaxed);
  pending_.store(count, std::memory_order_relaxed);
  const std::uint64_t first = caller_joins ? 0 : 1, threads = std::uint64_t(size()) - first;
  shares_[0].range.store(0, std::memory_order_release);
  for (std::uint64_t w = 0; w < threads; ++w) {
    const std::uint64_t begin = std::uint64_t(count) * w / threads, end = std::uint64_t(count) * (w + 1) / threads;
    shares_[first + w].range.store(begin | end << 32, std::memory_order_release);
  }
  generation_.fetch_add(1);  // wakes the workers (sequentially consistent)
  generation_.notify_all();
}

void ThreadPool::dispatch(int count, Thunk thunk, void* ctx) {
  publish(count, thunk, ctx, true);
  take_items(0);
  finish();
}

void ThreadPool::finish() {
  for (int spins = 0; pending_.load(std::memory_order_acquire) != 0; ++spins) {
    if (spins < 4096) {
      cpu_relax();
    } else {
      std::this_thread::yield();  // the thread running the last items may need this core
    }
  }
}

// An item claimed from a share is an item of the job running now, whatever job the thread
// woke for (shares are empty between jobs): the job cannot end before the item is done, so
// the function read after the claim is that job's.
void ThreadPool::take_items(int worker) {
  auto run_item = [&](int item) {
    thunk_.load(std::memory_order_relaxed)(ctx_.load(std::memory_order_relaxed), item, worker);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  };
  // Its own share from the front.
  std::atomic<std::uint64_t>& own = shares_[std::size_t(worker)].range;
  for (std::uint64_t r = own.load(std::memory_order_acquire); std::uint32_t(r) < std::uint32_t(r >> 32);) {
    if (own.compare_exchange_weak(r, r + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
      run_item(int(std::uint32_t(r)));
      r = own.load(std::memory_order_acquire);
    }
  }
  // Then the others' from the back, the next thread's first.
  const int threads = size();
  for (int k = 1; k < threads; ++k) {
    std::atomic<std::uint64_t>& other = shares_[std::size_t((worker + k) % threads)].range;
    for (std::uint64_t r = other.load(std::memory_order_acquire); std::uint32_t(r) < std::uint32_t(r >> 32);) {
      const std::uint64_t last = (r >> 32) - 1;
      if (other.compare_exchange_weak(r, (r & 0xffffffffu) | last << 32, std::memory_order_acq_rel,
                                      std::memory_order_acquire)) {
        run_item(int(last));
        r = other.load(std::memory_order_acquire);
      }
    }
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
  }
}

}  // namespace shadelab::fast
