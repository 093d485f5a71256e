#include "derive/context_matcher.h"

#include "lstring/branch_index.h"
#include "sylva/predefined_ids.h"

namespace sylva::derive {
namespace {

constexpr ModuleId kSB = rt::mid::SB;
constexpr ModuleId kEB = rt::mid::EB;

// Modules walked before a skip asks the index, where the view has one (a
// budget of 0 never asks): short branches cost less to walk than the
// index's lookups, and a pass that meets only short ones never builds it.
constexpr int kWalkedFirst = 16;

int walk_budget(const StringView& s) { return s.branches ? kWalkedFirst : 0; }

// The partner of the SB or EB at `bracket` from the index, if it lies in
// the view; kUnmatched otherwise, as a walk would find none there; kUnknown
// where the index cannot tell.
std::size_t indexed_eb(const StringView& s, std::size_t sb) {
  const std::size_t eb = s.branches->eb_of(sb);
  if (eb == BranchPartners::kUnknown) return eb;
  return eb >= s.begin && eb < s.end ? eb : BranchPartners::kUnmatched;
}
std::size_t indexed_sb(const StringView& s, std::size_t eb) {
  const std::size_t sb = s.branches->sb_of(eb);
  if (sb == BranchPartners::kUnknown) return sb;
  return sb >= s.begin && sb < s.end ? sb : BranchPartners::kUnmatched;
}

// Moves a cursor that reached the end of a ring to its start; false where the
// string ends (not a ring, or the ends were crossed once already).
bool wrap_forward(const StringView& s, ContextCursor& c) {
  if (c.at < s.end) return true;
  if (!s.ring || c.wrapped || s.begin == s.end) return false;
  c.at = s.begin;
  c.wrapped = true;
  return true;
}

bool wrap_backward(const StringView& s, ContextCursor& c) {
  if (c.at > s.begin) return true;
  if (!s.ring || c.wrapped || s.begin == s.end) return false;
  c.at = s.end;
  c.wrapped = true;
  return true;
}

// The two cursor skips are inlined into the matchers whatever their other
// callers: left to itself, the compiler stopped doing so once the skips by
// offset called them too, and newcontext-backward took 8% longer.

// From the SB at the cursor to just past its EB; false if it never closes.
[[gnu::always_inline]] inline bool skip_branch_forward(const StringView& s, ContextCursor& c) {
  const std::size_t sb = c.at;
  int depth = 0;
  int budget = walk_budget(s);  // an index means no ring: the cursor cannot wrap
  while (wrap_forward(s, c)) {
    if (budget > 0 && --budget == 0) {
      const std::size_t eb = indexed_eb(s, sb);
      if (eb != BranchPartners::kUnknown) {
        c.at = eb == BranchPartners::kUnmatched ? s.end : s.next(eb);
        return eb != BranchPartners::kUnmatched;
      }
    }
    const ModuleId id = s.id_at(c.at);
    c.at = s.next(c.at);
    if (id == kSB) ++depth;
    else if (id == kEB && --depth == 0) return true;
  }
  return false;
}

// From the EB just before the cursor back to its SB (the cursor ends on the
// SB); false if it never opens.
[[gnu::always_inline]] inline bool skip_branch_backward(const StringView& s, ContextCursor& c) {
  const std::size_t eb = s.previous(c.at);
  int depth = 0;
  int budget = walk_budget(s);
  while (wrap_backward(s, c)) {
    if (budget > 0 && --budget == 0) {
      const std::size_t sb = indexed_sb(s, eb);
      if (sb != BranchPartners::kUnknown) {
        c.at = sb == BranchPartners::kUnmatched ? s.begin : sb;
        return sb != BranchPartners::kUnmatched;
      }
    }
    c.at = s.previous(c.at);
    const ModuleId id = s.id_at(c.at);
    if (id == kEB) ++depth;
    else if (id == kSB && --depth == 0) return true;
  }
  return false;
}

}  // namespace

// The skips by offset never go across the ends of a ring.
std::size_t skip_branch_forward(const StringView& s, std::size_t sb) {
  StringView flat = s;
  flat.ring = false;
  ContextCursor c{sb, false};
  return skip_branch_forward(flat, c) ? c.at : s.end;
}

std::size_t skip_branch_backward(const StringView& s, std::size_t eb) {
  StringView flat = s;
  flat.ring = false;
  ContextCursor c{s.next(eb), false};
  return skip_branch_backward(flat, c) ? c.at : s.begin;
}

std::size_t find_unmatched_end(const StringView& s, std::size_t pos) {
  for (std::size_t at = pos; at < s.end;) {
    const ModuleId id = s.id_at(at);
    if (id == kEB) return at;
    at = id == kSB ? skip_branch_forward(s, at) : s.next(at);
  }
  return s.end;
}

bool match_right_context(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params) {
  ContextCursor c = from;
  // The SBs the pattern has entered and not left, innermost last: with an
  // index, the EB a pattern expects is the innermost one's partner, and the
  // rest of the branch need not be walked. Not where brackets are flat.
  constexpr int kMostOpen = 16;
  std::size_t open[kMostOpen];
  int depth = 0;
  const bool jump_to_eb =
      s.branches && !(skipped && (skipped[kSB] == kFlatBracket || skipped[kEB] == kFlatBracket));
  for (int k = 0; k < n; ++k) {
    const ModuleId want = pattern[k];
    int budget = want == kEB && jump_to_eb && depth > 0 && depth <= kMostOpen ? kWalkedFirst : 0;
    while (true) {
      if (budget > 0 && --budget == 0) {
        const std::size_t eb = indexed_eb(s, open[depth - 1]);
        if (eb == BranchPartners::kUnmatched) return false;
        if (eb != BranchPartners::kUnknown) c.at = eb;
      }
      if (!wrap_forward(s, c)) return false;
      const ModuleId id = s.id_at(c.at);
      if (id == want) {
        if (want == kSB && depth++ < kMostOpen) open[depth - 1] = c.at;
        else if (want == kEB && depth > 0) --depth;
        params[k] = module_params(s.data, c.at);
        c.at = s.next(c.at);
        break;
      }
      const bool flat = skipped && (id == kSB || id == kEB) && skipped[id] == kFlatBracket;
      if (id == kSB && !flat) {
        if (!skip_branch_forward(s, c)) return false;  // a lateral branch: topologically not in the way
      } else if (flat || want == kEB || (skipped && id != kEB && skipped[id])) {
        c.at = s.next(c.at);  // the rest of a branch the pattern ends, or an ignored module
      } else {
        return false;
      }
    }
  }
  from = c;
  return true;
}

bool match_left_context(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n, SkipTable skipped,
                        const unsigned char** params) {
  ContextCursor c = from;
  for (int k = n - 1; k >= 0; --k) {
    const ModuleId want = pattern[k];
    while (true) {
      if (!wrap_backward(s, c)) return false;
      const std::size_t start = s.previous(c.at);
      const ModuleId id = s.id_at(start);
      if (id == want) {
        params[k] = module_params(s.data, start);
        c.at = start;
        break;
      }
      if (id == kSB || (id != kEB && skipped && skipped[id])) {
        c.at = start;  // the start of this branch (the parent lies before it), or an ignored module
      } else if (id == kEB) {
        if (!skip_branch_backward(s, c)) return false;  // a sibling branch, not on the path to the root
      } else {
        return false;
      }
    }
  }
  from = c;
  return true;
}

bool match_right_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params) {
  ContextCursor from{pos, false};
  return match_right_context(s, from, pattern, n, skipped, params);
}

bool match_left_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                        const unsigned char** params) {
  ContextCursor from{pos, false};
  return match_left_context(s, from, pattern, n, skipped, params);
}

}  // namespace sylva::derive
