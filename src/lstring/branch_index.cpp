#include "lstring/branch_index.h"

#include <algorithm>
#include <atomic>
#include <utility>

#include "sylva/predefined_ids.h"

namespace sylva {

void BranchIndex::prepare(const StringView& string) {
  string_ = string;
  built_.store(false, std::memory_order_relaxed);
}

// One pass with a stack of open SBs, partners filled by rank as it goes.
// build_in_parts' way on one part (pairs kept, then ranked) made bush-context
// on one thread about a fifth slower: the pairs are fresh memory each step.
void BranchIndex::build() const {
  std::lock_guard<std::mutex> lock(building_);
  if (built_.load(std::memory_order_relaxed)) return;
  constexpr ModuleId kSB = rt::mid::SB;
  constexpr ModuleId kEB = rt::mid::EB;
  const StringView& s = string_;
  size_marks();
  std::fill(marks_.get(), marks_.get() + mark_words_, 0);
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
  count_marks();
  built_.store(true, std::memory_order_release);
}

void BranchIndex::size_marks() const {
  mark_words_ = string_.end / 64 + 1;
  if (mark_words_ > mark_room_) {
    marks_.reset(new std::uint64_t[mark_words_]);
    mark_room_ = mark_words_;
  }
}

std::size_t BranchIndex::count_marks() const {
  counts_.resize(mark_words_);
  superblock_counts_.assign((mark_words_ >> kSuperblockBits) + 1, 0);
  std::size_t before = 0;
  for (std::size_t w = 0; w < mark_words_; ++w) {
    if ((w & ((std::size_t{1} << kSuperblockBits) - 1)) == 0) superblock_counts_[w >> kSuperblockBits] = before;
    counts_[w] = static_cast<std::uint32_t>(before - superblock_counts_[w >> kSuperblockBits]);
    before += static_cast<std::size_t>(__builtin_popcountll(marks_[w]));
  }
  return before;
}

void BranchIndex::build_in_parts(const std::vector<std::size_t>& parts, const PartRunner& for_each_part) {
  constexpr ModuleId kSB = rt::mid::SB;
  constexpr ModuleId kEB = rt::mid::EB;
  const StringView& s = string_;
  const std::size_t n = parts.size();
  // Each part marks its brackets and pairs those it can on its own; the
  // rest are its EBs closing branches opened before it, then its SBs left
  // open, in that order.
  struct Part {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // SB and EB offsets
    std::vector<std::size_t> open_before, left_open;
  };
  std::vector<Part> found(n);
  size_marks();
  auto part_end = [&](std::size_t p) { return p + 1 < n ? parts[p + 1] : s.end; };
  for (std::size_t p = 0; p < n; ++p) marks_[parts[p] >> 6] = 0;  // words parts share
  marks_[s.end >> 6] = 0;
  for_each_part(n, [&](std::size_t p) {
    const std::size_t from = parts[p], to = part_end(p);
    if ((to >> 6) > (from >> 6) + 1) std::fill(&marks_[(from >> 6) + 1], &marks_[to >> 6], 0);
    Part& part = found[p];
    for (std::size_t at = from; at < to; at = s.next(at)) {
      const ModuleId id = s.id_at(at);
      if (id != kSB && id != kEB) continue;
      const std::uint64_t bit = std::uint64_t{1} << (at & 63);
      std::uint64_t& word = marks_[at >> 6];
      // Words a neighbouring part may also mark are shared.
      if ((at >> 6) == (from >> 6) || (at >> 6) == (to >> 6))
        std::atomic_ref<std::uint64_t>(word).fetch_or(bit, std::memory_order_relaxed);
      else
        word |= bit;
      if (id == kSB) {
        part.left_open.push_back(at);
      } else if (part.left_open.empty()) {
        part.open_before.push_back(at);
      } else {
        part.pairs.emplace_back(part.left_open.back(), at);
        part.left_open.pop_back();
      }
    }
  });
  partners_.assign(count_marks(), kUnmatched);
  for_each_part(n, [&](std::size_t p) {
    for (auto [sb, eb] : found[p].pairs) {
      partners_[rank(sb)] = eb;
      partners_[rank(eb)] = sb;
    }
  });
  std::vector<std::size_t> open;  // SBs of earlier parts still open
  for (const Part& part : found) {
    for (std::size_t eb : part.open_before) {
      if (open.empty()) break;
      partners_[rank(open.back())] = eb;
      partners_[rank(eb)] = open.back();
      open.pop_back();
    }
    open.insert(open.end(), part.left_open.begin(), part.left_open.end());
  }
  built_.store(true, std::memory_order_release);
}

}  // namespace sylva
