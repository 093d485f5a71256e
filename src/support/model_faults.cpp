#include "support/model_faults.h"

#include <cxxabi.h>
#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string>
#include <typeinfo>

#include "support/interruption.h"

// glibc: the top of the main thread's stack, as the program started.
extern "C" void* __libc_stack_end;

namespace sylva::model_faults {

namespace {

constexpr int kFatalSignals[] = {SIGSEGV, SIGFPE, SIGBUS, SIGILL, SIGABRT};

// What handled each fatal signal before: faults outside model code go back there.
struct sigaction previous_actions[NSIG];

// The calling thread's stack, to tell a stack overflow from another bad address.
thread_local std::uintptr_t stack_low = 0, stack_high = 0;

// A message built without allocating: a signal handler may not call malloc.
class SignalSafeText {
 public:
  SignalSafeText& operator<<(const char* text) {
    for (; text && *text && length_ < sizeof buffer_; ++text) buffer_[length_++] = *text;
    return *this;
  }
  SignalSafeText& operator<<(long number) {
    char digits[24];
    int n = 0;
    const bool negative = number < 0;
    unsigned long magnitude = negative ? 0UL - static_cast<unsigned long>(number) : static_cast<unsigned long>(number);
    do digits[n++] = static_cast<char>('0' + magnitude % 10);
    while ((magnitude /= 10) != 0);
    if (negative) *this << "-";
    while (n > 0 && length_ < sizeof buffer_) buffer_[length_++] = digits[--n];
    return *this;
  }
  void write_to(int fd) const {
    for (std::size_t done = 0; done < length_;) {
      const ssize_t n = ::write(fd, buffer_ + done, length_ - done);
      if (n <= 0) return;
      done += static_cast<std::size_t>(n);
    }
  }

 private:
  char buffer_[1024];
  std::size_t length_ = 0;
};

const char* describe(const siginfo_t& info) {
  const auto address = reinterpret_cast<std::uintptr_t>(info.si_addr);
  switch (info.si_signo) {
    case SIGFPE:
      switch (info.si_code) {
        case FPE_INTDIV: return "SIGFPE, integer division by zero";
        case FPE_INTOVF: return "SIGFPE, integer overflow";
        default: return "SIGFPE, arithmetic error";
      }
    case SIGSEGV:
      // The guard page below the stack, or just past it: the recursion ran out of stack.
      if (stack_high != 0 && address < stack_high && address + 256 * 1024 >= stack_low)
        return "SIGSEGV, stack overflow";
      if (address < 4096) return "SIGSEGV, null pointer";
      return "SIGSEGV, invalid memory access";
    case SIGBUS: return "SIGBUS, bus error";
    case SIGILL: return "SIGILL, illegal instruction";
    case SIGABRT: return "SIGABRT, aborted";
    default: return "fatal signal";
  }
}

void on_fatal_signal(int signal_number, siginfo_t* info, void* context) {
  if (!current_site || !current_site->what) {
    // Not the model's fault: as if this handler were not there. Returning
    // raises a fault again at once, and abort() raises SIGABRT again.
    const struct sigaction& previous = previous_actions[signal_number];
    if (previous.sa_flags & SA_SIGINFO) return previous.sa_sigaction(signal_number, info, context);
    if (previous.sa_handler != SIG_DFL && previous.sa_handler != SIG_IGN) return previous.sa_handler(signal_number);
    sigaction(signal_number, &previous, nullptr);
    if (info->si_code <= 0) raise(signal_number);  // sent, not raised by a fault: send it again
    return;
  }
  const CallSite& site = *current_site;
  SignalSafeText text;
  if (site.file) {
    text << site.file;
    if (site.line > 0) text << ":" << static_cast<long>(site.line);
    text << ": ";
  } else {
    text << "sylva: ";
  }
  text << "error: model crashed in " << site.what << " (" << describe(*info) << ") (step "
       << static_cast<long>(site.step_now()) << ")\n";
  text.write_to(STDERR_FILENO);
  interruption::clean_up_now();
  interruption::end_as_signal(signal_number);
}

void note_stack_bounds() {
  // The main thread's stack reaches from its top down by the stack's limit.
  // pthread_getattr_np would find the same bounds by reading /proc/self/maps,
  // 0.1 ms of every run's start.
  rlimit limit{};
  if (getpid() == gettid() && getrlimit(RLIMIT_STACK, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const auto top = reinterpret_cast<std::uintptr_t>(__libc_stack_end);
    stack_high = (top + 4095) / 4096 * 4096;
    stack_low = stack_high - limit.rlim_cur;
    return;
  }
  pthread_attr_t attributes;
  if (pthread_getattr_np(pthread_self(), &attributes) != 0) return;
  void* low = nullptr;
  std::size_t size = 0;
  if (pthread_attr_getstack(&attributes, &low, &size) == 0) {
    stack_low = reinterpret_cast<std::uintptr_t>(low);
    stack_high = stack_low + size;
  }
  pthread_attr_destroy(&attributes);
}

// The handler runs on a stack of its own: a stack overflow leaves none.
void give_thread_a_signal_stack() {
  stack_t current{};
  if (sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE)) return;  // one is there already
  constexpr std::size_t kSize = 64 * 1024;
  stack_t stack{};
  stack.ss_sp = std::malloc(kSize);  // kept for the thread's life
  if (!stack.ss_sp) return;
  stack.ss_size = kSize;
  if (sigaltstack(&stack, nullptr) != 0) std::free(stack.ss_sp);
}

}  // namespace

void install_handler() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction action {};
    action.sa_sigaction = on_fatal_signal;
    action.sa_flags = SA_SIGINFO | SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    for (int s : kFatalSignals) sigaction(s, &action, &previous_actions[s]);
  });
  thread_local bool thread_ready = false;
  if (thread_ready) return;
  thread_ready = true;
  note_stack_bounds();
  give_thread_a_signal_stack();
}

void block_all_but_faults() {
  sigset_t others;
  sigfillset(&others);
  for (int s : kFatalSignals) sigdelset(&others, s);
  pthread_sigmask(SIG_BLOCK, &others, nullptr);
}

void rethrow_as_model_error(const CallSite& site) {
  std::string what;
  try {
    throw;
  } catch (const std::exception& e) {
    int status = 0;
    char* name = abi::__cxa_demangle(typeid(e).name(), nullptr, nullptr, &status);
    what = std::string(status == 0 && name ? name : typeid(e).name()) + ": " + e.what();
    std::free(name);
  } catch (...) {
    const std::type_info* type = abi::__cxa_current_exception_type();
    int status = 0;
    char* name = type ? abi::__cxa_demangle(type->name(), nullptr, nullptr, &status) : nullptr;
    what = name && status == 0 ? name : type ? type->name() : "of unknown type";
    std::free(name);
  }
  throw ModelError(SourceLocation{site.file ? site.file : "sylva", site.line, 0},
                   std::string("model threw an exception in ") + site.what + " (" + what + ") (step " +
                       std::to_string(site.step_now()) + ")");
}

}  // namespace sylva::model_faults
