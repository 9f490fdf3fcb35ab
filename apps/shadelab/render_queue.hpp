// The lab's render queue: renders run on a fixed set of worker threads, taken from the clients
// in turn (each client's own requests in order), so that one client with many renders cannot
// starve the others; the queue is bounded, overall and per client, and a render that does not
// fit is refused at once (the server answers 503 with Retry-After). Knows nothing of HTTP or of
// scenes: a job is any function.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace shadelab::cli {

class RenderQueue {
 public:
  /// `workers` threads (at least 1); at most `capacity` jobs waiting and running in all, at
  /// most `per_client` of them from one client.
  RenderQueue(int workers, std::size_t capacity, std::size_t per_client);
  ~RenderQueue();
  RenderQueue(const RenderQueue&) = delete;
  RenderQueue& operator=(const RenderQueue&) = delete;

  /// Runs `job` on a worker and returns once it has run: true. False at once, without
  /// running it, when the queue or the client's share of it is full.
  bool run(const std::string& client, std::function<void()> job);

  int workers() const { return int(threads_.size()); }

 private:
  struct Job {
    std::function<void()> fn;
    bool done = false;
  };
  void work();

  std::mutex mutex_;
  std::condition_variable ready_;  // a job queued, or stopping
  std::condition_variable done_;   // a job finished
  std::map<std::string, std::deque<Job*>> waiting_;  // by client, in arrival order
  std::deque<std::string> turns_;  // clients with jobs waiting, the next to be served first
  std::map<std::string, std::size_t> held_;  // jobs waiting or running, by client
  std::size_t total_ = 0;                    // jobs waiting or running
  std::size_t capacity_, per_client_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace shadelab::cli
