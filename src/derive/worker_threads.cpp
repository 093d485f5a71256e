#include "derive/worker_threads.h"

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>

#include "lstring/run_limits.h"
#include "support/model_faults.h"

namespace sylva::derive {
namespace {

// The stack the fault handler runs on in a helper thread (a stack overflow
// leaves none), freed with the thread: the handler would otherwise keep one
// of its own for the life of a thread that lives for one pass.
class SignalStack {
 public:
  SignalStack() {
    stack_t stack{};
    stack.ss_sp = memory_.get();
    stack.ss_size = kSize;
    sigaltstack(&stack, nullptr);
  }
  ~SignalStack() {
    stack_t none{};
    none.ss_flags = SS_DISABLE;
    sigaltstack(&none, nullptr);
  }
  SignalStack(const SignalStack&) = delete;
  SignalStack& operator=(const SignalStack&) = delete;

 private:
  static constexpr std::size_t kSize = 64 * 1024;
  std::unique_ptr<char[]> memory_{new char[kSize]};
};

}  // namespace

void run_tasks(int threads, std::size_t count, const std::function<void(std::size_t)>& task) {
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0};
  RunBudget* budget = RunBudget::active();
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      try {
        task(k);
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  };
  const std::size_t helpers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count) - 1;
  std::vector<std::jthread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t)
    pool.emplace_back([&] {
      // A fault in model code on this thread is reported as on the caller's.
      SignalStack signal_stack;
      model_faults::install_handler();
      if (budget) {
        RunBudget::Scope scope(*budget);
        work();
      } else {
        work();
      }
    });
  work();
  pool.clear();  // joins
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace sylva::derive
