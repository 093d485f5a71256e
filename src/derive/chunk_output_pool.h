// Where the chunks of a parallel pass write their successors: buffers kept
// from pass to pass, so that their pages are faulted in once, not at every
// step. Each goes back, where it can, to the thread that wrote it last: its
// lines are in that core's cache, another thread's are in another's.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "lstring/module_string.h"
#include "lstring/page_memory.h"

namespace sylva::derive {

class ChunkOutputPool {
 public:
  // A cache line each: threads appending to neighbouring buffers would
  // otherwise write the same line at every module.
  struct alignas(64) Output {
    ModuleString string;
    std::thread::id writer;  // the thread that took it last
  };

  // An empty buffer for the calling thread, with room for `room` bytes: the
  // one it took last if the pool has it, else any, else a new one.
  std::unique_ptr<Output> take(std::size_t room);
  void give_back(std::unique_ptr<Output> output);
  // Frees all but `count` of the buffers in the pool.
  void keep_at_most(std::size_t count);
  std::size_t size() const;
  // The pages of the buffers in the pool, to be given back before it is freed.
  std::vector<page_memory::Pages> pages() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::unique_ptr<Output>> spare_;
};

}  // namespace sylva::derive
