// The lab's render queue (render_queue.hpp): per-client FIFOs served in turn.
#include "render_queue.hpp"

#include <algorithm>

namespace shadelab::cli {

RenderQueue::RenderQueue(int workers, std::size_t capacity, std::size_t per_client)
    : capacity_(std::max<std::size_t>(capacity, 1)), per_client_(std::max<std::size_t>(per_client, 1)) {
  for (int i = 0; i < std::max(workers, 1); ++i) threads_.emplace_back([this] { work(); });
}

RenderQueue::~RenderQueue() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  ready_.notify_all();
  for (std::thread& t : threads_) t.join();
}

bool RenderQueue::run(const std::string& client, std::function<void()> job) {
  Job j{std::move(job)};
  std::unique_lock<std::mutex> lock(mutex_);
  std::size_t& held = held_[client];
  if (stopping_ || total_ >= capacity_ || held >= per_client_) {
    if (held == 0) held_.erase(client);
    return false;
  }
  ++held, ++total_;
  std::deque<Job*>& mine = waiting_[client];
  if (mine.empty()) turns_.push_back(client);
  mine.push_back(&j);
  lock.unlock();
  ready_.notify_one();
  lock.lock();
  done_.wait(lock, [&] { return j.done; });
  if (--held_[client] == 0) held_.erase(client);
  --total_;
  return true;
}

void RenderQueue::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    ready_.wait(lock, [&] { return stopping_ || !turns_.empty(); });
    if (turns_.empty()) return;  // stopping, nothing left
    const std::string client = turns_.front();
    turns_.pop_front();
    std::deque<Job*>& mine = waiting_[client];
    Job* job = mine.front();
    mine.pop_front();
    if (mine.empty()) waiting_.erase(client);
    else turns_.push_back(client);  // its next job after every other client's
    lock.unlock();
    try {
      job->fn();
    } catch (...) {  // the job reports its own errors; a worker never dies of one
    }
    lock.lock();
    job->done = true;
    done_.notify_all();
  }
}

}  // namespace shadelab::cli
