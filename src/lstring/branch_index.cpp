#include "lstring/branch_index.h"

#include <utility>

#include "sylva/predefined_ids.h"

namespace sylva {

void BranchIndex::prepare(const StringView& string) {
  string_ = string;
  built_.store(false, std::memory_order_relaxed);
}

void BranchIndex::build() const {
  std::lock_guard<std::mutex> lock(building_);
  if (built_.load(std::memory_order_relaxed)) return;
  constexpr ModuleId kSB = rt::mid::SB;
  constexpr ModuleId kEB = rt::mid::EB;
  const StringView& s = string_;
  marks_.assign(s.end / 64 + 1, 0);
  partners_.clear();
  std::vector<std::pair<std::size_t, std::size_t>> open;  // rank and offset of each SB not closed yet
  for (std::size_t at = s.begin; at < s.end; at = s.next(at)) {
    const ModuleId id = s.id_at(at);
    if (id != kSB && id != kEB) continue;
    marks_[at >> 6] |= std::uint64_t{1} << (at & 63);
    if (id == kSB) {
      open.emplace_back(partners_.size(), at);
      partners_.push_back(kUnmatched);
    } else if (open.empty()) {
      partners_.push_back(kUnmatched);
    } else {
      partners_[open.back().first] = at;
      partners_.push_back(open.back().second);
      open.pop_back();
    }
  }
  counts_.resize(marks_.size());
  superblock_counts_.assign((marks_.size() >> kSuperblockBits) + 1, 0);
  std::size_t before = 0;
  for (std::size_t w = 0; w < marks_.size(); ++w) {
    if ((w & ((std::size_t{1} << kSuperblockBits) - 1)) == 0) superblock_counts_[w >> kSuperblockBits] = before;
    counts_[w] = static_cast<std::uint32_t>(before - superblock_counts_[w >> kSuperblockBits]);
    before += static_cast<std::size_t>(__builtin_popcountll(marks_[w]));
  }
  built_.store(true, std::memory_order_release);
}

}  // namespace sylva
