// Context matching on branching strings, as the LPFG manual's chapter 9 gives
// it. Right context skips lateral branches and, after an expected ']', the rest
// of the branch; left context sees the path to the root: '[' is passed over
// and a whole branch ending in ']' is skipped. Modules filtered out by
// ignore:/consider: are passed over; SB and EB always count.
#pragma once

#include <cstdint>

#include "lstring/module_string.h"
#include "sylva/predefined_ids.h"

namespace sylva::derive {

// `skipped[id]` is nonzero for modules context matching passes over; null
// means every module counts.
using SkipTable = const std::uint8_t*;
// The value of `skipped[SB]` or `skipped[EB]` where a right context steps
// over that bracket itself, into or out of a branch (cpfg's ignored [ and ]).
inline constexpr std::uint8_t kFlatBracket = 2;

// Where matching stands in a string: a byte offset, and whether it has gone
// once across the ends of a ring (it may not go across a second time, so a
// match never runs round the ring for ever).
struct ContextCursor {
  std::size_t at = 0;
  bool wrapped = false;
};

// The same matches from a cursor, which on success is moved past the matched
// modules: right context leaves it after the last, left context at the start
// of the leftmost. In-body context tests (InLeftContext ...) carry on from
// there. In a ring, branches may open before the end of the string and close
// after its start; skipping them goes across the ends.
bool match_right_context(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params);
bool match_left_context(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n, SkipTable skipped,
                        const unsigned char** params);

// The same, trying first inline what decides most matches in a rewriting
// pass: the modules right next to the cursor either are the pattern or rule
// it out. Where one is a bracket or an ignored module, or the string ends,
// the walks above decide.
inline bool match_right_context_here(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n,
                                     SkipTable skipped, const unsigned char** params) {
  std::size_t at = from.at;
  for (int k = 0; k < n; ++k) {
    const ModuleId want = pattern[k];
    if (at >= s.end || want == rt::mid::SB || want == rt::mid::EB) goto walk;
    const ModuleId id = s.id_at(at);
    if (id != want) {
      if (id == rt::mid::SB || id == rt::mid::EB || (skipped && skipped[id])) goto walk;
      return false;
    }
    params[k] = module_params(s.data, at);
    at = s.next(at);
  }
  from.at = at;
  return true;
walk:
  return match_right_context(s, from, pattern, n, skipped, params);
}

inline bool match_left_context_here(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n,
                                    SkipTable skipped, const unsigned char** params) {
  std::size_t at = from.at;
  for (int k = n - 1; k >= 0; --k) {
    if (at <= s.begin) goto walk;
    const std::size_t start = s.previous(at);
    const ModuleId id = s.id_at(start);
    if (id != pattern[k]) {
      if (id == rt::mid::SB || id == rt::mid::EB || (skipped && skipped[id])) goto walk;
      return false;
    }
    params[k] = module_params(s.data, start);
    at = start;
  }
  from.at = at;
  return true;
walk:
  return match_left_context(s, from, pattern, n, skipped, params);
}

// Matches `pattern` (n modules, in string order) starting at `pos` and going
// right. On success params[k] points at the parameters of the module matched
// by pattern[k].
bool match_right_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params);

// Matches `pattern` (n modules, in string order) so that its last module
// comes before `pos`, going left.
bool match_left_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                        const unsigned char** params);

// Offset just past the EB closing the branch whose SB is at `sb` (or the end).
std::size_t skip_branch_forward(const StringView& s, std::size_t sb);
// Offset of the first EB at this nesting level from `pos` on (or the end).
std::size_t find_unmatched_end(const StringView& s, std::size_t pos);
// Offset of the SB opening the branch whose EB starts at `eb` (or begin).
std::size_t skip_branch_backward(const StringView& s, std::size_t eb);

}  // namespace sylva::derive
