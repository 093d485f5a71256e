#include "derive/chunk_output_pool.h"

#include <algorithm>
#include <iterator>

#include "lstring/page_memory.h"

namespace sylva::derive {

std::unique_ptr<ChunkOutputPool::Output> ChunkOutputPool::take(std::size_t room) {
  const std::thread::id self = std::this_thread::get_id();
  std::unique_ptr<Output> output;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto own = std::find_if(spare_.rbegin(), spare_.rend(),
                            [&](const std::unique_ptr<Output>& spare) { return spare->writer == self; });
    if (own != spare_.rend()) {
      output = std::move(*own);
      spare_.erase(std::next(own).base());
    } else if (!spare_.empty()) {
      output = std::move(spare_.back());
      spare_.pop_back();
    }
  }
  if (!output) {
    // Room enough to be mapped, so its pages fault in a stretch at a time,
    // but only the room asked for faulted in now: a new buffer's pages are a
    // pass's own cost.
    output = std::make_unique<Output>();
    output->string.reserve_unwritten(std::max(room, page_memory::kMappedFrom));
  }
  output->string.clear();
  output->string.reserve(room);
  output->writer = self;
  return output;
}

void ChunkOutputPool::give_back(std::unique_ptr<Output> output) {
  std::lock_guard<std::mutex> lock(mutex_);
  spare_.push_back(std::move(output));
}

void ChunkOutputPool::keep_at_most(std::size_t count) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (spare_.size() > count) spare_.resize(count);
}

std::size_t ChunkOutputPool::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return spare_.size();
}

std::vector<page_memory::Pages> ChunkOutputPool::pages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<page_memory::Pages> pages;
  for (const std::unique_ptr<Output>& spare : spare_) pages.push_back(spare->string.faulted_in_pages());
  return pages;
}

}  // namespace sylva::derive
