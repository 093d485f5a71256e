// The brackets of a string being built, paired as it grows.
//
// New context reads the string a pass is building: forward derivation
// appends to it and reads new left context, which steps back over sibling
// branches (from an EB to its SB); backward derivation prepends to it and
// reads new right context, which steps over lateral branches and the rest of
// a branch (from an SB to its EB). Walked, each such step costs the branch's
// size. Caught up before each match, this index scans each module of the
// new string once in the whole pass and answers a step with a binary search.
// It keeps the pairs most recently completed only: new context is read next
// to where the string grows, and steps over branches just built; for an
// older one it says it cannot tell, and the matcher walks.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "lstring/branch_index.h"
#include "lstring/module_string.h"

namespace sylva {

class BuiltBranches final : public BranchPartners {
 public:
  enum class Growth {
    kAtEnd,    // appended to: pairs are found from the EB (sb_of)
    kAtStart,  // prepended to: pairs are found from the SB (eb_of)
  };

  // Forgets the string: a new pass builds a new one.
  void restart(Growth growth);
  // Takes in the modules `built` gained since the last call; then, until the
  // string changes again, partners are answered for this view of it.
  void catch_up(const StringView& built);

  std::size_t eb_of(std::size_t sb) const override;
  std::size_t sb_of(std::size_t eb) const override;

 private:
  // Brackets are kept by a key that does not change as the string grows:
  // the offset (kAtEnd), or the distance from the end (kAtStart).
  std::size_t partner_of(std::size_t key) const;

  static constexpr std::size_t kRecentPairs = 4096;

  void add_pair(std::size_t key, std::size_t partner_key);

  Growth growth_ = Growth::kAtEnd;
  bool forgot_ = false;   // pairs older than those in pairs_ were dropped
  std::size_t seen_ = 0;  // bytes taken in: from the start (kAtEnd), from the end (kAtStart)
  std::size_t end_ = 0;   // the view's end at the last catch-up
  std::vector<std::size_t> open_;                            // keys of brackets whose partner is not built yet
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;  // key and partner's key, keys increasing; the latest
};

}  // namespace sylva
