#include "roomscout/sim/map_worker.hpp"

#include <utility>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace roomscout::sim {

MapWorker::MapWorker(bool background) {
  if (background) thread_ = std::thread([this] { loop(); });
}

MapWorker::~MapWorker() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void MapWorker::post(std::function<void()> job) {
  if (!thread_.joinable()) {
    if (error_) return;
    try {
      job();
    } catch (...) {
      error_ = std::current_exception();
    }
    return;
  }
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
}

void MapWorker::drain() {
  wait();
  std::exception_ptr error;
  {
    std::lock_guard lock(mutex_);
    error = std::exchange(error_, nullptr);
  }
  if (error) std::rethrow_exception(error);
}

void MapWorker::wait() noexcept {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return jobs_.empty() && !running_job_; });
}

void MapWorker::loop() {
#ifdef __linux__
  // Below the episode's thread, which runs the robot and is the episode's critical path: when
  // the workers and it want more cores than there are, the workers wait. (Raising a thread's
  // nice value needs no privilege; if it fails, the thread keeps the normal priority.)
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kNiceIncrement);
#endif
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
    // The destructor still lets the queued jobs run: they may hold the last word of a map.
    if (jobs_.empty()) return;
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    running_job_ = true;
    const bool skip = static_cast<bool>(error_);
    lock.unlock();
    std::exception_ptr error;
    if (!skip) {
      try {
        job();
      } catch (...) {
        error = std::current_exception();
      }
    }
    job = nullptr;  // its captures go before the caller is told the queue is done
    lock.lock();
    if (error && !error_) error_ = error;
    running_job_ = false;
    if (jobs_.empty()) idle_.notify_all();
  }
}

}  // namespace roomscout::sim
