#include "derive/worker_threads.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

#include "lstring/run_limits.h"
#include "support/model_faults.h"

namespace sylva::derive {
namespace {

// The stack the fault handler runs on in a thread started for one pass (a
// stack overflow leaves none), freed with the thread: the handler would
// otherwise keep one of its own for the life of the thread.
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

// A helper thread reports a fault in model code as the caller's thread
// would, and leaves the process's other signals to the threads that were
// there before it.
void prepare_helper() {
  model_faults::block_all_but_faults();
  model_faults::install_handler();
}

// Spins for up to `limit` until `ready` says yes; false if it never did. A
// thread that sleeps on a condition variable takes 15-45 us to wake on a
// virtual machine (its core halts, and is woken through the hypervisor);
// passes follow each other closer than that within a step.
bool spin_until(const std::function<bool()>& ready, std::chrono::microseconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  for (int k = 0;; ++k) {
    if (ready()) return true;
    if ((k & 63) == 63 && std::chrono::steady_clock::now() >= end) return false;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
  }
}

// Helper threads kept between passes. Starting and joining fifteen threads
// for a pass took about 0.8 ms (bench/sylva_bench, Pass/16), and a step on
// many threads makes a few passes (the branch index, the productions, the
// decomposition), against some milliseconds of work each. The threads wait
// for the next pass instead: spinning for a while (kSpin), then asleep. One
// pass uses the pool at a time; a pass that finds it in use (another
// derivation on another thread) starts threads of its own.
class HelperPool {
 public:
  pid_t owner() const { return owner_; }

  // Runs `work` on `helpers` threads of the pool while the caller runs it
  // too, and returns once all have returned; false, having run nothing,
  // when the pool is in use.
  bool run(std::size_t helpers, const std::function<void()>& work) {
    std::unique_lock<std::mutex> pass(in_use_, std::try_to_lock);
    if (!pass) return false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (threads_ < helpers) {
        std::thread(&HelperPool::serve, this).detach();
        ++threads_;
      }
      work_ = &work;
      wanted_ = helpers;
      ++pass_number_;
      posted_.store(pass_number_, std::memory_order_release);
    }
    wake_.notify_all();
    work();
    // The tasks are all taken: a helper that has not woken yet has nothing
    // left to do, and need not be waited for.
    std::unique_lock<std::mutex> lock(mutex_);
    wanted_ = 0;
    lock.unlock();
    spin_until([&] { return working_.load(std::memory_order_acquire) == 0; }, kSpin);
    lock.lock();
    done_.wait(lock, [&] { return working_ == 0; });
    return true;
  }

 private:
  // A kept thread's signal stack is the one install_handler gives it for
  // its life.
  void serve() {
    prepare_helper();
    std::uint64_t last_pass = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      lock.unlock();
      spin_until([&] { return posted_.load(std::memory_order_acquire) != last_pass; }, kSpin);
      lock.lock();
      wake_.wait(lock, [&] { return pass_number_ != last_pass && wanted_ > 0; });
      last_pass = pass_number_;
      --wanted_;
      ++working_;
      const std::function<void()>& work = *work_;
      lock.unlock();
      work();
      lock.lock();
      if (--working_ == 0) done_.notify_all();
    }
  }

  // Long enough to span the serial work between the passes of a step (the
  // cuts of the string, the sums of a parallel pass) and between steps;
  // short enough that a pool left idle soon stops taking a core.
  static constexpr std::chrono::microseconds kSpin{200};

  const pid_t owner_ = getpid();
  std::mutex in_use_;  // held by the pass using the pool
  std::mutex mutex_;   // guards what follows
  std::condition_variable wake_, done_;
  std::size_t threads_ = 0;
  std::uint64_t pass_number_ = 0;
  std::atomic<std::uint64_t> posted_{0};  // pass_number_, read by spinning helpers without the lock
  std::size_t wanted_ = 0;   // helpers the pass still asks for
  std::atomic<std::size_t> working_{0};  // helpers running the pass's work; read spinning without the lock
  const std::function<void()>* work_ = nullptr;
};

// Never destroyed: its threads wait for work until the process ends. A
// forked process has none of its parent's threads, and makes a pool of its
// own.
HelperPool& helper_pool() {
  static std::atomic<HelperPool*> pool{new HelperPool};
  HelperPool* current = pool.load(std::memory_order_acquire);
  if (current->owner() == getpid()) return *current;
  auto* own = new HelperPool;
  if (pool.compare_exchange_strong(current, own, std::memory_order_acq_rel)) return *own;
  delete own;  // another thread of this process made one first
  return *current;
}

}  // namespace

void run_tasks(int threads, std::size_t count, const std::function<void(std::size_t)>& task) {
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      try {
        task(k);
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  };
  // Threads besides the caller's: none for a single task, or none at all.
  std::size_t helpers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count);
  if (helpers > 0) --helpers;
  if (helpers == 0) {
    work();
  } else {
    // Helpers check the run's limits as the caller does.
    RunBudget* budget = RunBudget::active();
    const std::function<void()> helper_work = [&] {
      if (!budget) return work();
      RunBudget::Scope scope(*budget);
      work();
    };
    if (!helper_pool().run(helpers, helper_work)) {
      std::vector<std::jthread> own;
      own.reserve(helpers);
      for (std::size_t t = 0; t < helpers; ++t)
        own.emplace_back([&] {
          SignalStack signal_stack;
          prepare_helper();
          helper_work();
        });
      work();
    }  // threads of its own join here
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace sylva::derive
