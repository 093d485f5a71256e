// Splits independent per-query work over the machine's cores. Each query's
// answer depends only on the shared, read-only scene, so the result does not
// depend on how the work is split.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace sylva::env::light {

// How many threads parallel_for uses for `count` items.
inline std::size_t parallel_threads(std::size_t count) {
  constexpr std::size_t kMinimumPerThread = 256;
  std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  return std::min(threads, std::max<std::size_t>(1, count / kMinimumPerThread));
}

// Calls work(begin, end, thread) on disjoint ranges covering [0, count), on
// parallel_threads(count) threads (thread = 0, 1, ...) taking blocks in turn
// (queries in dense parts of a scene cost more); rethrows the first exception.
template <class Work>
void parallel_for(std::size_t count, Work&& work) {
  std::size_t threads = parallel_threads(count);
  if (threads <= 1) {
    work(std::size_t{0}, count, std::size_t{0});
    return;
  }
  constexpr std::size_t kBlock = 64;
  std::atomic<std::size_t> next_block{0};
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      try {
        for (;;) {
          std::size_t begin = next_block.fetch_add(kBlock);
          if (begin >= count) break;
          work(begin, std::min(count, begin + kBlock), t);
        }
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

}  // namespace sylva::env::light
