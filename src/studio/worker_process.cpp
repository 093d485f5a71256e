#include "studio/worker_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <chrono>
#include <cstring>
#include <vector>

namespace sylva::studio {
namespace {

constexpr std::size_t kConsoleLimit = 64 * 1024;

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

WorkerProcess::WorkerProcess(std::vector<std::string> command, std::string working_dir, WorkerLimits limits)
    : command_(std::move(command)), working_dir_(std::move(working_dir)), limits_(limits) {}

WorkerProcess::~WorkerProcess() { stop(); }

void WorkerProcess::start() {
  // A worker that dies while a request is written to it is reported by the
  // failed write; the signal would end this whole program instead.
  static std::once_flag ignore_sigpipe;
  std::call_once(ignore_sigpipe, [] { ::signal(SIGPIPE, SIG_IGN); });
  int requests[2], answers[2], console[2];
  if (::pipe2(requests, O_CLOEXEC) != 0 || ::pipe2(answers, O_CLOEXEC) != 0 || ::pipe2(console, O_CLOEXEC) != 0)
    throw WorkerFailure("crash", std::string("cannot start a worker: ") + std::strerror(errno));
  std::vector<char*> argv;
  for (std::string& a : command_) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid < 0) throw WorkerFailure("crash", std::string("cannot start a worker: ") + std::strerror(errno));
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec.
    ::setpgid(0, 0);  // its own group, so a kill reaches the compiler it runs
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);  // the server's blocked signals are its own
    const int in = ::fcntl(requests[0], F_DUPFD, 10), out = ::fcntl(answers[1], F_DUPFD, 10);
    ::dup2(in, 3);
    ::dup2(out, 4);
    ::dup2(console[1], 1);
    ::dup2(console[1], 2);
    ::close_range(5, ~0U, 0);
    rlimit memory{limits_.memory_bytes, limits_.memory_bytes};
    ::setrlimit(RLIMIT_AS, &memory);
    if (!working_dir_.empty() && ::chdir(working_dir_.c_str()) != 0) ::_exit(126);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(requests[0]);
  ::close(answers[1]);
  ::close(console[1]);
  pid_ = pid;
  requests_ = requests[1];
  answers_ = answers[0];
  console_thread_ = std::thread([this, fd = console[0]] { read_console(fd); });
}

void WorkerProcess::read_console(int fd) {
  char buffer[4096];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    std::lock_guard lock(console_mutex_);
    console_.append(buffer, static_cast<std::size_t>(n));
    if (console_.size() > kConsoleLimit) console_.erase(0, console_.size() - kConsoleLimit);
  }
  ::close(fd);
}

std::string WorkerProcess::take_console() {
  std::lock_guard lock(console_mutex_);
  return std::exchange(console_, {});
}

WorkerMessage WorkerProcess::request(const nlohmann::json& request, double timeout_seconds) {
  if (!running()) start();
  if (!write_message(requests_, {request, {}})) throw WorkerFailure("crash", reap());
  pollfd answer{answers_, POLLIN, 0};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      stop();
      throw WorkerFailure("timeout", "the model took longer than " + std::to_string(static_cast<int>(timeout_seconds)) +
                                         " s (the studio's time limit, --time-limit) and was stopped");
    }
    const int ready = ::poll(&answer, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready > 0) break;
    if (ready < 0 && errno != EINTR) throw WorkerFailure("crash", std::strerror(errno));
  }
  WorkerMessage message;
  bool complete = false;
  try {
    complete = read_message(answers_, message);
  } catch (const std::runtime_error& e) {
    stop();
    throw WorkerFailure("crash", e.what());
  }
  if (!complete) throw WorkerFailure("crash", reap());
  return message;
}

std::string WorkerProcess::reap() {
  int status = 0;
  std::string why = "the model's process ended";
  if (pid_ > 0 && ::waitpid(pid_, &status, 0) == pid_) {
    if (WIFSIGNALED(status)) {
      const int signal = WTERMSIG(status);
      why = std::string("the model crashed: ") + ::strsignal(signal) + " (signal " + std::to_string(signal) + ")";
      if (signal == SIGSEGV) why += ", e.g. a null or dangling pointer in a production or a function";
      if (signal == SIGFPE) why += ", e.g. an integer division by zero";
    } else if (WIFEXITED(status)) {
      why = "the model's process exited with status " + std::to_string(WEXITSTATUS(status));
    }
  }
  if (pid_ > 0) ::kill(-pid_, SIGKILL);  // what it started (a compiler) goes with it
  pid_ = -1;
  close_fd(requests_);
  close_fd(answers_);
  if (console_thread_.joinable()) console_thread_.join();
  // A fault in the model's code: the worker said where (support/model_faults.h).
  if (WIFSIGNALED(status)) {
    std::lock_guard lock(console_mutex_);
    const std::size_t at = console_.rfind(": error: model crashed in ");
    if (at != std::string::npos) {
      const std::size_t begin = console_.rfind('\n', at) + 1;  // npos + 1: the first line
      why = console_.substr(begin, console_.find('\n', at) - begin);
    }
  }
  return why;
}

void WorkerProcess::interrupt() {
  const pid_t pid = pid_;
  if (pid > 0) ::kill(-pid, SIGKILL);
}

void WorkerProcess::stop() {
  if (pid_ <= 0) return;
  ::kill(-pid_, SIGKILL);
  reap();  // closes the pipes and ends the console's thread
}

}  // namespace sylva::studio
