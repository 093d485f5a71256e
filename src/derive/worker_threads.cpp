#include "derive/worker_threads.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "lstring/run_limits.h"
#include "support/model_faults.h"

namespace sylva::derive {

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
