#include "support/interruption.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace sylva::interruption {

namespace {

// Fixed tables of atomics: a signal handler can neither allocate nor lock.
// A run has a handful of temporary files and at most a few children at once.
std::array<std::atomic<char*>, 256> temporary_files{};
std::array<std::atomic<pid_t>, 64> child_groups{};

void on_signal(int signal_number) {
  clean_up_now();
  end_as_signal(signal_number);
}

}  // namespace

void end_as_signal(int signal_number) {
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  sigaction(signal_number, &default_action, nullptr);
  sigset_t unblocked;
  sigemptyset(&unblocked);
  sigaddset(&unblocked, signal_number);
  sigprocmask(SIG_UNBLOCK, &unblocked, nullptr);
  raise(signal_number);
  _exit(128 + signal_number);
}

void install_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // While one signal is being handled the others wait: cleaning up happens once.
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    sigaction(s, nullptr, &previous);
    // A signal ignored by whoever started us (nohup) stays ignored.
    if (previous.sa_handler == SIG_IGN) continue;
    sigaction(s, &action, nullptr);
  }
}

void clean_up_now() {
  for (std::atomic<pid_t>& group : child_groups)
    if (const pid_t g = group.load(); g > 0) kill(-g, SIGTERM);
  for (std::atomic<char*>& file : temporary_files)
    if (const char* path = file.exchange(nullptr)) unlink(path);  // the copy leaks: the process is ending
}

TemporaryFile::TemporaryFile(const std::string& path) {
  char* copy = strdup(path.c_str());
  if (!copy) return;
  for (std::size_t i = 0; i < temporary_files.size(); ++i) {
    char* expected = nullptr;
    if (temporary_files[i].compare_exchange_strong(expected, copy)) {
      slot_ = static_cast<int>(i);
      return;
    }
  }
  std::free(copy);
}

TemporaryFile::~TemporaryFile() {
  if (slot_ >= 0) std::free(temporary_files[static_cast<std::size_t>(slot_)].exchange(nullptr));
}

ChildProcessGroup::ChildProcessGroup(pid_t group) {
  for (std::size_t i = 0; i < child_groups.size(); ++i) {
    pid_t expected = 0;
    if (child_groups[i].compare_exchange_strong(expected, group)) {
      slot_ = static_cast<int>(i);
      return;
    }
  }
}

ChildProcessGroup::~ChildProcessGroup() {
  if (slot_ >= 0) child_groups[static_cast<std::size_t>(slot_)].store(0);
}

}  // namespace sylva::interruption
