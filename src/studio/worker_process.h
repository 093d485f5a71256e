// A studio worker (worker.h) as a child process of the server, with limits:
// its address space is capped (a model that explodes in size fails to
// allocate instead of taking the machine), every request has a time limit
// (a model that loops is killed with everything it started, a compiler
// included), and a worker that dies is reported, not followed. The next
// request starts a fresh worker.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "studio/worker_protocol.h"

namespace sylva::studio {

struct WorkerLimits {
  std::size_t memory_bytes = std::size_t{8} << 30;  // address space
};

// The worker is gone: it crashed, ran out of time or of memory. `kind` is
// "crash", "timeout" or "memory".
class WorkerFailure : public std::runtime_error {
 public:
  WorkerFailure(std::string kind, const std::string& message) : std::runtime_error(message), kind_(std::move(kind)) {}
  const std::string& kind() const { return kind_; }

 private:
  std::string kind_;
};

class WorkerProcess {
 public:
  // `command`: the program and its arguments that run_worker(3, 4) serves
  // (requests on descriptor 3, answers on 4); it runs in `working_dir`.
  WorkerProcess(std::vector<std::string> command, std::string working_dir, WorkerLimits limits);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  // Sends `request` and waits at most `timeout_seconds` for the answer,
  // starting the worker first if there is none. Throws WorkerFailure when
  // the worker dies or is too slow (it is then stopped).
  WorkerMessage request(const nlohmann::json& request, double timeout_seconds);

  // What the worker (the model's printf, compiler messages) printed since the
  // last call, at most the last 64 KiB.
  std::string take_console();

  bool running() const { return pid_ > 0; }
  // Kills the worker and everything it started.
  void stop();
  // Kills them from another thread than the one waiting for an answer,
  // which then sees the worker gone.
  void interrupt();

 private:
  void start();
  // Why the worker ended, once it has.
  std::string reap();
  void read_console(int fd);

  std::vector<std::string> command_;
  std::string working_dir_;
  WorkerLimits limits_;
  std::atomic<pid_t> pid_ = -1;
  int requests_ = -1, answers_ = -1;
  std::thread console_thread_;
  std::mutex console_mutex_;
  std::string console_;
};

}  // namespace sylva::studio
