#include "experiment/local_processes.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <system_error>

namespace sylva::experiment {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void write_all(int fd, const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    at += static_cast<std::size_t>(n);
  }
}

RunResult failed(long number, const std::string& why) {
  RunResult result;
  result.number = number;
  result.error = why;
  return result;
}

}  // namespace

LocalProcesses::LocalProcesses(int capacity, RunFunction run, double timeout_seconds)
    : capacity_(capacity), run_(std::move(run)), timeout_seconds_(timeout_seconds) {}

LocalProcesses::~LocalProcesses() {
  for (auto& [fd, child] : children_) {
    ::kill(child.pid, SIGKILL);
    ::waitpid(child.pid, nullptr, 0);
    ::close(fd);
  }
}

void LocalProcesses::start(const RunSpec& run) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "experiment: pipe");
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = ::fork();
  if (pid < 0) throw std::system_error(errno, std::generic_category(), "experiment: fork");
  if (pid == 0) {
    ::close(fds[0]);
    std::string text;
    try {
      text = run_(run);
    } catch (const std::exception& error) {
      text = encode_result(failed(run.number, error.what()));
    }
    write_all(fds[1], text);
    ::close(fds[1]);
    ::_exit(0);  // no atexit handlers or static destructors of the parent's
  }
  ::close(fds[1]);
  children_[fds[0]] = Child{run.number, pid, {}, now_seconds()};
}

RunResult LocalProcesses::ended(int fd, Child& child) {
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  ::close(fd);
  if (WIFSIGNALED(status))
    return failed(child.number, "the run's process was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                                    strsignal(WTERMSIG(status)) + ")");
  if (child.output.empty())
    return failed(child.number, "the run's process ended (status " + std::to_string(WEXITSTATUS(status)) + ") with no result");
  try {
    return decode_result(child.output);
  } catch (const std::exception& error) {
    return failed(child.number, std::string("the run's result could not be read: ") + error.what());
  }
}

std::vector<RunResult> LocalProcesses::collect(int timeout_ms) {
  std::vector<RunResult> results;
  if (children_.empty()) return results;
  std::vector<pollfd> fds;
  for (const auto& [fd, child] : children_) fds.push_back({fd, POLLIN, 0});
  const int ready = ::poll(fds.data(), fds.size(), timeout_ms);
  if (ready < 0 && errno != EINTR) throw std::system_error(errno, std::generic_category(), "experiment: poll");
  for (const pollfd& p : fds) {
    if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
    Child& child = children_.at(p.fd);
    char buffer[65536];
    const ssize_t n = ::read(p.fd, buffer, sizeof buffer);
    if (n > 0) {
      child.output.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    results.push_back(ended(p.fd, child));
    children_.erase(p.fd);
  }
  if (timeout_seconds_ > 0) {
    const double now = now_seconds();
    for (auto it = children_.begin(); it != children_.end();) {
      if (now - it->second.started <= timeout_seconds_) {
        ++it;
        continue;
      }
      ::kill(it->second.pid, SIGKILL);
      ::waitpid(it->second.pid, nullptr, 0);
      ::close(it->first);
      char text[64];
      std::snprintf(text, sizeof text, "the run took longer than %g s and was stopped", timeout_seconds_);
      results.push_back(failed(it->second.number, text));
      it = children_.erase(it);
    }
  }
  return results;
}

}  // namespace sylva::experiment
