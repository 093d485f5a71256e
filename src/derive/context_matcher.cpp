#include "derive/context_matcher.h"

#include "sylva/predefined_ids.h"

namespace sylva::derive {
namespace {
constexpr ModuleId kSB = rt::mid::SB;
constexpr ModuleId kEB = rt::mid::EB;
}  // namespace

std::size_t skip_branch_forward(const StringView& s, std::size_t sb) {
  int depth = 0;
  for (std::size_t at = sb; at < s.end; at = s.next(at)) {
    ModuleId id = s.id_at(at);
    if (id == kSB) ++depth;
    else if (id == kEB && --depth == 0) return s.next(at);
  }
  return s.end;
}

std::size_t find_unmatched_end(const StringView& s, std::size_t pos) {
  int depth = 0;
  for (std::size_t at = pos; at < s.end; at = s.next(at)) {
    ModuleId id = s.id_at(at);
    if (id == kSB) ++depth;
    else if (id == kEB && depth-- == 0) return at;
  }
  return s.end;
}

std::size_t skip_branch_backward(const StringView& s, std::size_t eb) {
  int depth = 0;
  for (std::size_t at = s.next(eb); at > s.begin;) {
    at = s.previous(at);
    ModuleId id = s.id_at(at);
    if (id == kEB) ++depth;
    else if (id == kSB && --depth == 0) return at;
  }
  return s.begin;
}

namespace {

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

// From the SB at the cursor to just past its EB; false if it never closes.
bool skip_branch_forward(const StringView& s, ContextCursor& c) {
  int depth = 0;
  while (wrap_forward(s, c)) {
    const ModuleId id = s.id_at(c.at);
    c.at = s.next(c.at);
    if (id == kSB) ++depth;
    else if (id == kEB && --depth == 0) return true;
  }
  return false;
}

// From the EB just before the cursor back to its SB (the cursor ends on the
// SB); false if it never opens.
bool skip_branch_backward(const StringView& s, ContextCursor& c) {
  int depth = 0;
  while (wrap_backward(s, c)) {
    c.at = s.previous(c.at);
    const ModuleId id = s.id_at(c.at);
    if (id == kEB) ++depth;
    else if (id == kSB && --depth == 0) return true;
  }
  return false;
}

}  // namespace

bool match_right_context(const StringView& s, ContextCursor& from, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params) {
  ContextCursor c = from;
  for (int k = 0; k < n; ++k) {
    const ModuleId want = pattern[k];
    while (true) {
      if (!wrap_forward(s, c)) return false;
      const ModuleId id = s.id_at(c.at);
      if (id == want) {
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
