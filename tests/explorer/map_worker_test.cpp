// MapWorker: jobs run in the order posted, errors come back from drain(), and a worker
// without a thread runs each job at once.

#include "roomscout/explorer/map_worker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace roomscout {
namespace {

TEST(MapWorker, RunsJobsOneAtATimeInTheOrderPosted) {
  MapWorker worker(true);
  EXPECT_TRUE(worker.background());
  std::vector<int> done;  // touched by the worker only, until drain() returns
  const std::thread::id caller = std::this_thread::get_id();
  bool off_thread = true;
  for (int i = 0; i < 2000; ++i) {
    worker.post([&, i] {
      off_thread = off_thread && std::this_thread::get_id() != caller;
      done.push_back(i);
    });
  }
  worker.drain();
  ASSERT_EQ(done.size(), 2000u);
  for (int i = 0; i < 2000; ++i) ASSERT_EQ(done[i], i);
  EXPECT_TRUE(off_thread);
}

TEST(MapWorker, WithoutAThreadRunsEachJobAtOnce) {
  MapWorker worker(false);
  EXPECT_FALSE(worker.background());
  int runs = 0;
  worker.post([&] { ++runs; });
  EXPECT_EQ(runs, 1);
  worker.post([&] { ++runs; });
  EXPECT_EQ(runs, 2);
  EXPECT_NO_THROW(worker.drain());
}

TEST(MapWorker, DrainRethrowsTheFirstErrorAndLaterJobsAreSkipped) {
  for (const bool background : {true, false}) {
    SCOPED_TRACE(background);
    MapWorker worker(background);
    int runs = 0;
    worker.post([&] { ++runs; });
    worker.post([] { throw std::runtime_error("first"); });
    worker.post([] { throw std::runtime_error("second"); });
    worker.post([&] { ++runs; });
    try {
      worker.drain();
      ADD_FAILURE() << "drain() did not throw";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "first");
    }
    EXPECT_EQ(runs, 1);
    // The error was reported once; the worker takes jobs again.
    worker.post([&] { ++runs; });
    EXPECT_NO_THROW(worker.drain());
    EXPECT_EQ(runs, 2);
  }
}

TEST(MapWorker, WaitKeepsTheErrorForDrain) {
  MapWorker worker(true);
  bool ran = false;
  worker.post([&] {
    ran = true;
    throw std::runtime_error("kept");
  });
  worker.wait();
  EXPECT_TRUE(ran);
  EXPECT_THROW(worker.drain(), std::runtime_error);
  EXPECT_NO_THROW(worker.drain());
}

#ifdef __linux__
TEST(MapWorker, RunsBelowThePriorityOfTheThreadThatMadeIt) {
  const auto niceOfThisThread = [] {
    errno = 0;
    return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  };
  const int caller = niceOfThisThread();
  int worker_nice = caller;
  MapWorker worker(true);
  worker.post([&] { worker_nice = niceOfThisThread(); });
  worker.drain();
  // Higher nice, lower priority (unless the caller already sits at the lowest, 19).
  EXPECT_EQ(worker_nice, std::min(19, caller + 5));
  EXPECT_EQ(niceOfThisThread(), caller);  // the caller's own priority is untouched
}
#endif

TEST(MapWorker, DestructorLetsQueuedJobsFinish) {
  int runs = 0;
  {
    MapWorker worker(true);
    for (int i = 0; i < 100; ++i) worker.post([&] { ++runs; });
  }
  EXPECT_EQ(runs, 100);
}

}  // namespace
}  // namespace roomscout
