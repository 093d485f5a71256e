#include "env/external_program.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include "env/environment.h"
#include "support/diagnostic.h"

namespace sylva::env {
namespace {

using Clock = std::chrono::steady_clock;

// Seconds since construction as a double: limits are compared in seconds, so
// a huge --env-timeout never overflows the clock's integer ticks.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  Clock::time_point start_ = Clock::now();
};

void append_float(std::string& out, float v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, " %.9g", static_cast<double>(v));
  out += buffer;
}

void append_module(std::string& out, const ModuleRecord& m) {
  out += ' ';
  out += m.symbol;
  out += ' ';
  out += std::to_string(m.parameters.size());
  for (float v : m.parameters) append_float(out, v);
}

struct FieldLine {
  const char* name;
  const TurtleFormat CommSpec::*format;
};
// The order turtle fields are sent in.
constexpr FieldLine kTurtleLines[] = {
    {"position", &CommSpec::position}, {"heading", &CommSpec::heading},
    {"left", &CommSpec::left},         {"up", &CommSpec::up},
    {"line-width", &CommSpec::line_width}, {"scale-factor", &CommSpec::scale_factor},
};

// Writes to a pipe whose reader may be gone without the process receiving
// SIGPIPE: the signal is blocked for the write and a pending one consumed.
ssize_t write_without_sigpipe(int fd, const char* data, std::size_t size) {
  sigset_t pipe_signal, old;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &old);
  const ssize_t n = ::write(fd, data, size);
  const int error = errno;
  if (n < 0 && error == EPIPE) {
    const timespec zero{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &zero);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  errno = error;
  return n;
}

// "1 parameter", "2 parameters".
std::string parameter_count_text(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " parameter" : " parameters");
}

std::string shortened(const std::string& line) {
  return line.size() > 80 ? line.substr(0, 77) + "..." : line;
}

}  // namespace

struct ExternalProgramField::Process {
  std::string name;  // as on the executable: line
  SourceLocation where;
  double timeout_seconds = 60;
  CommSpec spec;
  pid_t pid = -1;
  int to_program = -1;    // the program's standard input
  int from_program = -1;  // the program's standard output
  std::string received;   // read, not yet split into lines
  bool failed = false;
  bool ended = false;  // its output closed while an answer was awaited

  [[noreturn]] void fail(const std::string& what) {
    failed = true;
    stop(true);
    throw ModelError(where, "environmental program '" + name + "' " + what);
  }

  // "exited with status 3", "was killed by signal 11" ...
  std::string exit_description() {
    if (pid < 0) return "ended";
    int status = 0;
    // The program closed its output; give it a moment to be reaped.
    for (int k = 0; k < 200; ++k) {
      const pid_t r = ::waitpid(pid, &status, WNOHANG);
      if (r == pid) {
        pid = -1;
        if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
        if (WIFSIGNALED(status)) return std::string("was killed by signal ") + std::to_string(WTERMSIG(status)) +
                                        " (" + strsignal(WTERMSIG(status)) + ")";
        return "ended";
      }
      if (r < 0) break;
      ::usleep(5000);
    }
    return "closed its output";
  }

  void close_pipes() {
    if (to_program >= 0) ::close(to_program);
    if (from_program >= 0) ::close(from_program);
    to_program = from_program = -1;
  }

  // Ends the process: at once with `kill`, otherwise after "exit" and up to
  // the timeout.
  void stop(bool kill) {
    if (pid < 0) {
      close_pipes();
      return;
    }
    if (!kill && to_program >= 0) {
      static const char exit_line[] = "exit\n";
      write_without_sigpipe(to_program, exit_line, sizeof exit_line - 1);
    }
    close_pipes();
    const Stopwatch since_exit;
    const double limit = kill ? 0.0 : timeout_seconds;
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
      if (since_exit.seconds() >= limit) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        break;
      }
      ::usleep(2000);
    }
    pid = -1;
  }

  // Hands every complete line received to `on_line` until one equals
  // `last`; true when it came (the lines after it stay for later).
  template <class OnLine>
  bool take_lines(const std::string& last, OnLine& on_line) {
    std::size_t newline;
    while ((newline = received.find('\n')) != std::string::npos) {
      std::string line = received.substr(0, newline);
      received.erase(0, newline + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line == last) return true;
      on_line(line);
    }
    return false;
  }

  [[noreturn]] void fail_timeout(const std::string& during) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", timeout_seconds);
    fail("did not answer within " + std::string(seconds) + " seconds " + during +
         " (it was stopped; --env-timeout sets the limit)");
  }

  // Writes what the pipe takes of `text` from `written` on. A program that
  // closed its input makes `can_write` false: its output then tells why.
  void write_some(const std::string& text, std::size_t& written, bool& can_write) {
    const ssize_t n = write_without_sigpipe(to_program, text.data() + written, text.size() - written);
    if (n > 0) written += static_cast<std::size_t>(n);
    else if (n < 0 && errno != EAGAIN && errno != EINTR) can_write = false;
  }

  // Appends what the program sent to `received`; false at the end of its output.
  bool read_some(const std::string& during, bool answered) {
    char buffer[65536];
    const ssize_t n = ::read(from_program, buffer, sizeof buffer);
    if (n > 0) {
      received.append(buffer, static_cast<std::size_t>(n));
      return true;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return true;
    // A program that ends after answering has done its part of this pass;
    // the next one reports it.
    if (answered) return false;
    ended = true;
    fail(exit_description() + " " + during);
  }

  // Sends `text` while handing each line the program sends to `on_line`,
  // until it has sent a line equal to `last` and all of `text` is written.
  // The protocol lets a program send `last` before it has read everything:
  // stopping the writing then would leave the rest of `text` unsent and the
  // next exchange would start in the middle of a line.
  template <class OnLine>
  void exchange(const std::string& text, const std::string& last, const std::string& during, OnLine&& on_line) {
    const Stopwatch since_start;
    std::size_t written = 0;
    bool can_write = true;
    bool answered = false;
    for (;;) {
      if (!answered) answered = take_lines(last, on_line);
      const bool writing = can_write && written < text.size();
      if (answered && !writing) return;
      const double left = timeout_seconds - since_start.seconds();
      if (left <= 0) fail_timeout(during);
      pollfd fds[2];
      nfds_t count = 0;
      fds[count++] = pollfd{from_program, POLLIN, 0};
      if (writing) fds[count++] = pollfd{to_program, POLLOUT, 0};
      // At most a second at a time: the deadline is checked between waits,
      // and no timeout however large overflows the wait.
      const int wait_ms = static_cast<int>(std::ceil(std::min(left, 1.0) * 1000));
      const int ready = ::poll(fds, count, wait_ms);
      if (ready < 0) {
        if (errno == EINTR) continue;
        fail(std::string("could not be waited for: ") + std::strerror(errno));
      }
      if (count > 1 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) write_some(text, written, can_write);
      if ((fds[0].revents & (POLLIN | POLLERR | POLLHUP)) && !read_some(during, answered)) return;
    }
  }
};

ExternalProgramField::ExternalProgramField(const std::string& executable, const ProgramInvocation& invocation,
                                           const CommSpec& spec, double timeout_seconds)
    : process_(std::make_unique<Process>()) {
  Process& p = *process_;
  p.name = invocation.program;
  p.where = SourceLocation{invocation.e_file, invocation.e_file_line, 0};
  p.timeout_seconds = timeout_seconds;
  p.spec = spec;

  int in_pipe[2], out_pipe[2], exec_status[2];
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(exec_status, O_CLOEXEC) != 0)
    throw ModelError(p.where, "cannot start environmental program '" + p.name + "': " + std::strerror(errno));

  std::vector<std::string> words{executable};
  words.insert(words.end(), invocation.arguments.begin(), invocation.arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const std::string directory = invocation.directory.empty() ? "." : invocation.directory.string();

  const pid_t pid = ::fork();
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec.
    ::dup2(in_pipe[0], STDIN_FILENO);
    ::dup2(out_pipe[1], STDOUT_FILENO);
    int error = 0;
    if (::chdir(directory.c_str()) != 0) error = errno;
    else {
      ::execv(argv[0], argv.data());
      error = errno;
    }
    ssize_t ignored = ::write(exec_status[1], &error, sizeof error);
    (void)ignored;
    ::_exit(127);
  }
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  ::close(exec_status[1]);
  if (pid < 0) {
    const int error = errno;
    ::close(in_pipe[1]);
    ::close(out_pipe[0]);
    ::close(exec_status[0]);
    throw ProgramNotStarted(p.where, "cannot start environmental program '" + p.name + "': " + std::strerror(error));
  }
  p.pid = pid;
  p.to_program = in_pipe[1];
  p.from_program = out_pipe[0];
  ::fcntl(p.to_program, F_SETFL, ::fcntl(p.to_program, F_GETFL) | O_NONBLOCK);

  int exec_error = 0;
  const ssize_t got = ::read(exec_status[0], &exec_error, sizeof exec_error);
  ::close(exec_status[0]);
  if (got == static_cast<ssize_t>(sizeof exec_error)) {
    p.stop(true);
    throw ProgramNotStarted(p.where, "cannot start environmental program '" + p.name + "' (" + executable +
                                         "): " + std::strerror(exec_error));
  }

  std::string header = std::string(kProtocolGreeting) + "\n";
  header += std::string("following-module ") + (spec.following_module ? "yes" : "no") + "\n";
  for (const FieldLine& field : kTurtleLines) {
    const TurtleFormat& format = spec.*field.format;
    if (format.count > 0) header += std::string("format ") + field.name + " " + format.text + "\n";
  }
  header += std::string("verbose ") + (spec.verbose ? "yes" : "no") + "\n";
  header += "end-header\n";
  try {
    p.exchange(header, "ready", "before saying it was ready", [&p](const std::string& line) {
      p.fail("sent '" + shortened(line) + "' instead of 'ready' (is it built with the sylva_comm library, and does " +
             "it write nothing else to its standard output?)");
    });
  } catch (const ModelError& error) {
    // A program that ends before it is ready did not start, for the
    // communication library as for lpfg.
    if (p.ended) throw ProgramNotStarted(error.where(), error.message());
    throw;
  }
}

ExternalProgramField::~ExternalProgramField() {
  if (process_) process_->stop(process_->failed);
}

std::string ExternalProgramField::encode_pass(std::span<const Query> queries, const CommSpec& spec, int step) {
  std::string out = "begin " + std::to_string(step) + "\n";
  for (const Query& q : queries) {
    out += "query " + std::to_string(q.id);
    append_module(out, q.module);
    out += '\n';
    const TurtleReport& t = q.turtle;
    const float width[1] = {t.line_width}, scale[1] = {t.scale_factor};
    const float* values[] = {t.position.data(), t.heading.data(), t.left.data(), t.up.data(), width, scale};
    for (std::size_t k = 0; k < std::size(kTurtleLines); ++k) {
      const TurtleFormat& format = spec.*kTurtleLines[k].format;
      if (format.count == 0) continue;
      out += kTurtleLines[k].name;
      out += ' ';
      out += format_turtle_values(format, values[k]);
      out += '\n';
    }
    if (spec.following_module) {
      out += "following";
      if (!q.following.symbol.empty()) append_module(out, q.following);
      out += '\n';
    }
  }
  out += "end\n";
  return out;
}

void ExternalProgramField::answer(std::span<const Query> queries, std::span<Answer> answers, int step) {
  Process& p = *process_;
  if (p.failed || p.pid < 0)
    throw ModelError(p.where, "environmental program '" + p.name + "' is no longer running");
  std::unordered_map<std::uint64_t, std::size_t> by_id;
  for (std::size_t k = 0; k < queries.size(); ++k) by_id.emplace(queries[k].id, k);

  const std::string during = "during the environmental pass before step " + std::to_string(step + 1);
  p.exchange(encode_pass(queries, p.spec, step), "end", during, [&](const std::string& line) {
    // "ID INDEX VALUE"
    const char* s = line.c_str();
    char* end = nullptr;
    errno = 0;
    const unsigned long long id = std::strtoull(s, &end, 10);
    bool ok = end != s && errno == 0 && *end == ' ';
    long index = -1;
    float value = 0;
    if (ok) {
      s = end;
      index = std::strtol(s, &end, 10);
      ok = end != s && *end == ' ' && index >= 0 && index < kMaxParameters;
    }
    if (ok) {
      s = end;
      value = std::strtof(s, &end);
      while (*end == ' ' || *end == '\t') ++end;
      ok = end != s && *end == '\0';
    }
    if (!ok)
      p.fail("answered '" + shortened(line) + "' " + during + "; expected 'ID INDEX VALUE' (INDEX from 0 to " +
             std::to_string(kMaxParameters - 1) + ") or 'end'");
    const auto found = by_id.find(id);
    if (found == by_id.end())
      p.fail("answered module " + std::to_string(id) + ", which was not asked about, " + during);
    const ModuleRecord& module = queries[found->second].module;
    if (static_cast<std::size_t>(index) >= module.parameters.size())
      p.fail("answered parameter " + std::to_string(index) + " of module " + std::to_string(id) + " (" +
             module.symbol + "), which has " + parameter_count_text(module.parameters.size()) + ", " + during);
    answers[found->second].assign(static_cast<int>(index), value);
  });
}

void ExternalProgramField::finish() {
  if (process_) process_->stop(process_->failed);
}

}  // namespace sylva::env
