#pragma once
// A background thread for the map updates that nothing reads while the robot explores (the
// point cloud, the skeleton graph, and the rooms when the strategy ignores them), as a robot
// runs its map builders as nodes beside its planner. Jobs run one at a time
// in the order they were posted, so a map comes out the same as if every update had run at
// once on the caller's thread; a worker made without a thread does exactly that. The thread
// runs at a lower priority than the one that made it (Linux: nice + kNiceIncrement), so it
// takes what the explorer's thread leaves of the cores.

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace roomscout {

class MapWorker {
 public:
  /// @param background false: post() runs each job at once on the caller's thread
  explicit MapWorker(bool background);
  /// Waits for the jobs posted so far (their errors are dropped: call drain() to see them).
  ~MapWorker();
  MapWorker(const MapWorker&) = delete;
  MapWorker& operator=(const MapWorker&) = delete;

  bool background() const { return thread_.joinable(); }
  /// Runs `job` after every job posted before it. A job's inputs must be its own (copies):
  /// the caller goes on while it runs.
  void post(std::function<void()> job);
  /// Waits until every posted job has run, then rethrows the first error a job threw (the
  /// jobs posted after a failed one are skipped: the maps they would update are suspect).
  void drain();
  /// Waits until every posted job has run; an error stays for drain(). For destructors of
  /// what the jobs refer to.
  void wait() noexcept;

 private:
  /// The worker thread's nice value above its maker's (lower priority, see the constructor).
  static constexpr int kNiceIncrement = 5;
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<std::function<void()>> jobs_;
  bool running_job_ = false;
  bool stop_ = false;
  std::exception_ptr error_;
  std::thread thread_;  ///< last: starts once the members above exist
};

}  // namespace roomscout
