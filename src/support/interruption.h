// Ctrl-C, kill and hang-up during a run: what the program has started is
// undone before it ends. Temporary files and child process groups are
// registered while they exist; the handlers remove the files, stop the
// groups, and end the process as the signal itself would (so the shell sees
// the conventional status, 130 for Ctrl-C).
#pragma once

#include <sys/types.h>

#include <string>

namespace sylva::interruption {

// Installs the handlers for SIGINT, SIGTERM and SIGHUP. Front doors that
// handle these signals themselves (the studio) do not call it.
void install_handlers();

// Ends the process as `signal_number` would have: its default action, then
// the signal again (128 + the number if it is somehow survived). For
// handlers, after they have done their part. Async-signal-safe.
[[noreturn]] void end_as_signal(int signal_number);

// Removes every registered temporary file and stops every registered process
// group. Async-signal-safe: a fatal-signal handler may call it too.
void clean_up_now();

// A file that must not outlive an interrupted run. Registration only: the
// owner still removes or renames the file as it would anyway.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& path);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

 private:
  int slot_ = -1;  // -1: every slot taken, not registered
};

// A child process group (a compiler and what it starts) that an interrupted
// run stops with SIGTERM, so the compiler removes its own temporary files.
class ChildProcessGroup {
 public:
  explicit ChildProcessGroup(pid_t group);
  ~ChildProcessGroup();
  ChildProcessGroup(const ChildProcessGroup&) = delete;
  ChildProcessGroup& operator=(const ChildProcessGroup&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace sylva::interruption
