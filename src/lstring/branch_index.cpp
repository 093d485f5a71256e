#include "lstring/branch_index.h"

#include <algorithm>
#include <atomic>
#include <utility>

#include "sylva/predefined_ids.h"

namespace sylva {
namespace {

constexpr ModuleId kSB = rt::mid::SB;
constexpr ModuleId kEB = rt::mid::EB;

}  // namespace

void BranchIndex::prepare(const StringView& string) {
  string_ = string;
  built_.store(false, std::memory_order_relaxed);
}

void BranchIndex::build() const {
  std::lock_guard<std::mutex> lock(building_);
  if (built_.load(std::memory_order_relaxed)) return;
  build_from({string_.begin}, [](std::size_t n, const std::function<void(std::size_t)>& task) {
    for (std::size_t p = 0; p < n; ++p) task(p);
  });
}

void BranchIndex::build_in_parts(const std::vector<std::size_t>& parts, const PartRunner& for_each_part) {
  build_from(parts, for_each_part);
}

// Two passes over each part: the first marks where brackets start (a walk
// over the modules), the second goes through the marks in order, pairing
// brackets with a stack of the part's open SBs and writing each partner at
// its rank. What a part leaves open (EBs closing branches opened before it,
// SBs still open at its end, as many as the branches are deep) is paired
// across the parts at the end.
void BranchIndex::build_from(const std::vector<std::size_t>& parts, const PartRunner& for_each_part) const {
  const StringView& s = string_;
  const std::size_t n = parts.size();
  auto part_end = [&](std::size_t p) { return p + 1 < n ? parts[p + 1] : s.end; };
  size_marks();
  std::fill(marks_.get(), marks_.get() + (parts[0] >> 6), 0);  // before the string's begin
  for (std::size_t p = 0; p < n; ++p) marks_[parts[p] >> 6] = 0;  // words parts share
  marks_[s.end >> 6] = 0;
  for_each_part(n, [&](std::size_t p) {
    const std::size_t from = parts[p], to = part_end(p);
    if ((to >> 6) > (from >> 6) + 1) std::fill(&marks_[(from >> 6) + 1], &marks_[to >> 6], 0);
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
    }
  });
  const std::size_t brackets = count_marks(n, for_each_part);
  wide_ = s.end >= std::min<std::size_t>(narrow_below_, kNarrowUnmatched);
  if (wide_) wide_partners_.make_room(brackets);
  else narrow_partners_.make_room(brackets);
  struct Bracket {
    std::size_t rank, offset;
  };
  struct Loose {
    std::vector<Bracket> closing_earlier, open;  // in string order
  };
  std::vector<Loose> loose(n);
  for_each_part(n, [&](std::size_t p) {
    const std::size_t from = parts[p], to = part_end(p);
    std::vector<Bracket>& open = loose[p].open;
    std::size_t r = rank(from);  // the brackets before this part
    for (std::size_t word = from >> 6; word <= (to - 1) >> 6 && from < to; ++word) {
      std::uint64_t bits = marks_[word];
      if (word == from >> 6) bits &= ~std::uint64_t{0} << (from & 63);
      if (word == (to - 1) >> 6 && (to & 63)) bits &= (std::uint64_t{1} << (to & 63)) - 1;
      for (; bits; bits &= bits - 1, ++r) {
        const std::size_t at = (word << 6) + static_cast<std::size_t>(__builtin_ctzll(bits));
        if (s.id_at(at) == kSB) {
          open.push_back({r, at});
        } else if (open.empty()) {
          loose[p].closing_earlier.push_back({r, at});
        } else {
          set_partner(open.back().rank, at);
          set_partner(r, open.back().offset);
          open.pop_back();
        }
      }
    }
  });
  std::vector<Bracket> open;  // SBs of earlier parts still open
  for (const Loose& part : loose) {
    for (const Bracket& eb : part.closing_earlier) {
      if (open.empty()) {
        set_partner(eb.rank, kUnmatched);
        continue;
      }
      set_partner(open.back().rank, eb.offset);
      set_partner(eb.rank, open.back().offset);
      open.pop_back();
    }
    open.insert(open.end(), part.open.begin(), part.open.end());
  }
  for (const Bracket& sb : open) set_partner(sb.rank, kUnmatched);
  built_.store(true, std::memory_order_release);
}

void BranchIndex::size_marks() const {
  mark_words_ = string_.end / 64 + 1;
  marks_.make_room(mark_words_);
}

std::size_t BranchIndex::count_marks(std::size_t ranges, const PartRunner& for_each_range) const {
  // The words in ranges, each counted on its own: its marks, then (once the
  // marks before it are summed) the counts of its words. A superblock starts
  // a range, so its base is a range's sum.
  constexpr std::size_t kSuperblockWords = std::size_t{1} << kSuperblockBits;
  std::vector<std::size_t> starts;
  const std::size_t step = std::max<std::size_t>(mark_words_ / std::max<std::size_t>(ranges, 1), 1);
  for (std::size_t w = 0; w < mark_words_;) {
    starts.push_back(w);
    w = std::min(w + step, (w / kSuperblockWords + 1) * kSuperblockWords);
  }
  const std::size_t n = starts.size();
  auto range_end = [&](std::size_t r) { return r + 1 < n ? starts[r + 1] : mark_words_; };
  std::vector<std::size_t> before(n + 1, 0);
  for_each_range(n, [&](std::size_t r) {
    std::size_t count = 0;
    for (std::size_t w = starts[r]; w < range_end(r); ++w) count += bit_count(marks_[w]);
    before[r + 1] = count;
  });
  for (std::size_t r = 0; r < n; ++r) before[r + 1] += before[r];
  counts_.make_room(mark_words_);
  superblock_counts_.assign((mark_words_ >> kSuperblockBits) + 1, 0);
  for (std::size_t r = 0; r < n; ++r)
    if (starts[r] % kSuperblockWords == 0) superblock_counts_[starts[r] >> kSuperblockBits] = before[r];
  for_each_range(n, [&](std::size_t r) {
    std::size_t count = before[r];
    for (std::size_t w = starts[r]; w < range_end(r); ++w) {
      counts_[w] = static_cast<std::uint32_t>(count - superblock_counts_[w >> kSuperblockBits]);
      count += bit_count(marks_[w]);
    }
  });
  return before[n];
}

}  // namespace sylva
