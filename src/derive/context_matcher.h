// Context matching on branching strings, as the LPFG manual's chapter 9 gives
// it. Right context skips lateral branches and, after an expected ']', the rest
// of the branch; left context sees the path to the root: '[' is passed over
// and a whole branch ending in ']' is skipped. Modules filtered out by
// ignore:/consider: are passed over; SB and EB always count.
#pragma once

#include <cstdint>

#include "lstring/module_string.h"

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
