#pragma once
// Helpers for the ROS tests: a child process that dies with the test (whatever ends the
// test: a failed assertion, a crash, ctest's timeout), a rosmaster on a free local port, and
// waiting for a latched topic.

#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <ros/ros.h>

#include "support/temp_dir.hpp"

namespace roomscout::ros1::test {

using roomscout::test::TempDir;

/// A program started with its own environment additions, output to a log file. The
/// destructor stops it: SIGINT, then SIGKILL after a grace period. The kernel kills it too
/// if the test process dies first (PR_SET_PDEATHSIG), so no stray master or node survives.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
               const std::filesystem::path& log)
      : log_(log) {
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      ::setpgid(0, 0);
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
      }
      for (const auto& [k, v] : env) ::setenv(k.c_str(), v.c_str(), 1);
      std::vector<char*> args;
      for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      ::execvp(args[0], args.data());
      ::_exit(127);
    }
  }
  ~ChildProcess() { stop(); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Exit status once it exited (-signal when killed); nullopt while it runs.
  std::optional<int> poll() {
    if (status_) return status_;
    int st = 0;
    if (::waitpid(pid_, &st, WNOHANG) == pid_)
      status_ = WIFEXITED(st) ? WEXITSTATUS(st) : -WTERMSIG(st);
    return status_;
  }
  /// Waits up to `timeout` for it to exit.
  std::optional<int> wait(std::chrono::duration<double> timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!poll() && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return poll();
  }
  /// Asks it to stop (SIGINT), kills it after `grace`; returns its exit status.
  int stop(std::chrono::duration<double> grace = std::chrono::seconds(5)) {
    if (pid_ <= 0) return -1;
    if (!poll()) {
      ::kill(-pid_, SIGINT);
      if (!wait(grace)) {
        ::kill(-pid_, SIGKILL);
        wait(std::chrono::seconds(5));
      }
    }
    return status_.value_or(-1);
  }
  std::string output() const {
    std::ifstream in(log_);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
  std::filesystem::path log_;
};

/// A TCP port no one listens on now (the kernel's pick).
inline int freePort() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(s);
  return ntohs(a.sin_port);
}

inline bool portOpen(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(s);
  return ok;
}

/// A rosmaster on a free port, with ROS_HOME and logs in a temporary folder. env() is what a
/// node started against it needs.
class RosMaster {
 public:
  RosMaster() : port_(freePort()) {
    std::filesystem::create_directories(dir_.path() / "ros_home");
    env_ = {{"ROS_MASTER_URI", uri()},
            {"ROS_HOSTNAME", "localhost"},
            {"ROS_HOME", (dir_.path() / "ros_home").string()},
            {"ROS_LOG_DIR", (dir_.path() / "ros_home" / "log").string()},
            {"PYTHONUNBUFFERED", "1"}};
    master_.emplace(std::vector<std::string>{"/usr/bin/python3", "/usr/bin/rosmaster", "--core",
                                             "-p", std::to_string(port_)},
                    env_, dir_.path() / "rosmaster.log");
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!portOpen(port_)) {
      if (master_->poll() || std::chrono::steady_clock::now() > end) {
        throw std::runtime_error("rosmaster did not start: " + master_->output());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  std::string uri() const { return "http://localhost:" + std::to_string(port_); }
  const std::map<std::string, std::string>& env() const { return env_; }
  const std::filesystem::path& dir() const { return dir_.path(); }

  /// Joins this process to the master as a ROS node (once per process: ctest runs each test
  /// in a process of its own).
  void initClient(const std::string& name) const {
    if (ros::isInitialized()) {
      // roscpp joins one master per process, for good: a second would hang on the first's.
      throw std::logic_error(
          "one ROS system test per process: run them through ctest or --gtest_filter");
    }
    for (const auto& [k, v] : env_) ::setenv(k.c_str(), v.c_str(), 1);
    std::map<std::string, std::string> remappings = {{"__master", uri()},
                                                     {"__hostname", "localhost"}};
    ros::init(remappings, name,
              ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
  }

  /// Starts a node of the ROS package folder with `args` (e.g. "_world:=small_house").
  std::unique_ptr<ChildProcess> node(const std::string& binary, const std::string& name,
                                     std::vector<std::string> args) const {
    std::vector<std::string> argv = {binary, "__name:=" + name};
    argv.insert(argv.end(), args.begin(), args.end());
    return std::make_unique<ChildProcess>(argv, env_, dir_.path() / (name + ".log"));
  }

 private:
  TempDir dir_;
  int port_;
  std::map<std::string, std::string> env_;
  std::optional<ChildProcess> master_;
};

/// Spins this process's callbacks until `done()` holds or `timeout` (wall) passes, checking
/// `alive()` (e.g. that the nodes still run) on the way.
inline bool spinUntil(
    const std::function<bool()>& done, std::chrono::duration<double> timeout,
    const std::function<bool()>& alive = [] { return true; }) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    ros::spinOnce();
    if (done()) return true;
    if (!alive()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

}  // namespace roomscout::ros1::test
