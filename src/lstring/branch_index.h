// Where each branch of a string opens and closes, found in constant time.
//
// Context matching skips whole branches: a right context steps over lateral
// branches and, after a pattern's bracket, over the rest of a branch; a left
// context steps back over sibling branches. Walked module by module, a step
// over a branching structure costs the size of the subtrees skipped, which
// on a tree of depth d is about d times the string. The index answers each
// skip with a few memory reads. It is built (a walk over the string, then
// a pass over the brackets it marked) the first time a long branch is
// skipped, so a pass that meets none pays nothing.
//
// Layout: a bit per byte of the string marks where a bracket (SB or EB)
// starts; a bracket's rank is the count of brackets before its 64-byte word
// (counted per block of words, plus a base per superblock so counts stay
// 32-bit) and the marked bits before it in the word; the rank indexes the
// offset of its partner.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "lstring/module_string.h"
#include "lstring/page_memory.h"

namespace sylva {

// Where the partner of a bracket is, as context matching asks it: an SB's
// EB, an EB's SB. kUnmatched where the string has none; kUnknown where this
// source cannot tell (the matcher then walks).
class BranchPartners {
 public:
  static constexpr std::size_t kUnmatched = ~std::size_t{0};
  static constexpr std::size_t kUnknown = kUnmatched - 1;

  virtual std::size_t eb_of(std::size_t sb) const = 0;
  virtual std::size_t sb_of(std::size_t eb) const = 0;

 protected:
  ~BranchPartners() = default;
};

class BranchIndex final : public BranchPartners {
 public:
  // Partners are kept in 4 bytes for strings shorter than `narrow_below`
  // bytes (at most 4 GiB, the default), in 8 for longer ones.
  explicit BranchIndex(std::size_t narrow_below = kNarrowUnmatched) : narrow_below_(narrow_below) {}

  // The string to index on first use, from begin to end (`string.ring` is
  // ignored); it must not change while the index is in use. Not to be
  // called while another thread may be asking for partners.
  void prepare(const StringView& string);

  // Builds the index prepared now, on several threads: `parts` are offsets
  // of modules that cut the string into parts (the first at its begin),
  // and `for_each_part(n, task)` calls task(0) ... task(n - 1), on threads
  // of its own or not. For a pass that will need the index anyway.
  using PartRunner = std::function<void(std::size_t count, const std::function<void(std::size_t)>& task)>;
  void build_in_parts(const std::vector<std::size_t>& parts, const PartRunner& for_each_part);
  // Whether the index was built since it was prepared: the pass needed it.
  bool built() const { return built_.load(std::memory_order_acquire); }
  // The pages of its arrays, to be given back before it is freed.
  std::vector<page_memory::Pages> pages() const {
    return {marks_.pages(), counts_.pages(), narrow_partners_.pages(), wide_partners_.pages()};
  }

  std::size_t eb_of(std::size_t sb) const override { return partner(sb); }
  std::size_t sb_of(std::size_t eb) const override { return partner(eb); }

  // The offset of the bracket paired with the one starting at `bracket`: an
  // SB's EB or an EB's SB; kUnmatched where the string has none. Safe to
  // call from several threads at once.
  std::size_t partner(std::size_t bracket) const {
    if (!built_.load(std::memory_order_acquire)) build();
    const std::size_t r = rank(bracket);
    if (wide_) return wide_partners_[r];
    const std::uint32_t narrow = narrow_partners_[r];
    return narrow == kNarrowUnmatched ? kUnmatched : narrow;
  }

 private:
  static constexpr int kSuperblockBits = 20;  // words per superblock: 2^20 (64 MiB of string)
  static constexpr std::uint32_t kNarrowUnmatched = ~std::uint32_t{0};

  void set_partner(std::size_t rank, std::size_t offset) const {
    if (wide_) wide_partners_[rank] = offset;
    else narrow_partners_[rank] = offset == kUnmatched ? kNarrowUnmatched : static_cast<std::uint32_t>(offset);
  }

  std::size_t rank(std::size_t bracket) const {
    const std::size_t word = bracket >> 6;
    const std::uint64_t before = marks_[word] & ((std::uint64_t{1} << (bracket & 63)) - 1);
    return superblock_counts_[word >> kSuperblockBits] + counts_[word] +
           bit_count(before);
  }
  // The bits set in `word`. Where the build targets no popcount instruction
  // (x86-64's baseline) the builtin is a call into libgcc; this is not.
  static std::size_t bit_count(std::uint64_t word) {
#ifdef __POPCNT__
    return static_cast<std::size_t>(__builtin_popcountll(word));
#else
    word -= (word >> 1) & 0x5555555555555555ULL;
    word = (word & 0x3333333333333333ULL) + ((word >> 2) & 0x3333333333333333ULL);
    word = (word + (word >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
    return static_cast<std::size_t>((word * 0x0101010101010101ULL) >> 56);
#endif
  }
  void build() const;
  void build_from(const std::vector<std::size_t>& parts, const PartRunner& for_each_part) const;
  // Room for the marks of `string_`, not cleared.
  void size_marks() const;
  // Counts the marks before each word, in about `ranges` ranges of words
  // run as the parts are; returns them all.
  std::size_t count_marks(std::size_t ranges, const PartRunner& for_each_range) const;

  StringView string_;
  mutable std::mutex building_;
  mutable std::atomic<bool> built_{false};
  // Bit k of word w: a bracket starts at byte 64w + k. Not a vector, so a
  // parallel build can clear the words on the threads that mark them. The
  // marks and the partners grow with the string and keep their pages from
  // step to step: reallocated at every step, they were faulted in afresh at
  // every step, on every thread.
  mutable page_memory::GrowingArray<std::uint64_t> marks_;
  mutable std::size_t mark_words_ = 0;
  mutable page_memory::GrowingArray<std::uint32_t> counts_;  // brackets before word w within its superblock
  mutable std::vector<std::size_t> superblock_counts_;       // brackets before each superblock
  // Partners by rank, in 4 bytes while every offset fits, else in 8: pairing
  // writes half as much, and the index of a long string takes half the
  // memory.
  std::size_t narrow_below_;
  mutable bool wide_ = false;
  mutable page_memory::GrowingArray<std::uint32_t> narrow_partners_;
  mutable page_memory::GrowingArray<std::size_t> wide_partners_;
};

}  // namespace sylva
