#include "roomscout/explorer/map_worker.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#ifdef __linux__
#include <cerrno>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace roomscout {

namespace {

/// The calling thread's nice value; none where it cannot be read (or off Linux).
std::optional<int> niceOfThisThread() {
#ifdef __linux__
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  if (nice != -1 || errno == 0) return nice;
#endif
  return std::nullopt;
}

/// Sets the calling thread's nice value (raising it needs no privilege); a failure leaves it.
void setNiceOfThisThread([[maybe_unused]] int nice) {
#ifdef __linux__
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), nice);
#endif
}

}  // namespace

MapWorker::MapWorker(bool background) {
  if (!background) return;
  // Below the thread that makes the worker (the explorer's, which runs the robot and is its
  // critical path, perhaps itself under `nice`): when the workers and it want more
  // cores than there are, the workers wait.
  const std::optional<int> caller_nice = niceOfThisThread();
  thread_ = std::thread([this, caller_nice] {
    if (caller_nice) setNiceOfThisThread(std::min(19, *caller_nice + kNiceIncrement));
    loop();
  });
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

}  // namespace roomscout
