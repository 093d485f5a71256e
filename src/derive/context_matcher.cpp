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

bool match_right_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                         const unsigned char** params) {
  std::size_t at = pos;
  bool wrapped = false;
  for (int k = 0; k < n; ++k) {
    const ModuleId want = pattern[k];
    while (true) {
      if (at >= s.end) {
        if (!s.ring || wrapped) return false;
        at = s.begin;
        wrapped = true;
      }
      const ModuleId id = s.id_at(at);
      if (id == want) {
        params[k] = module_params(s.data, at);
        at = s.next(at);
        break;
      }
      if (id == kSB) {
        at = skip_branch_forward(s, at);  // a lateral branch: topologically not in the way
      } else if (want == kEB || (skipped && id != kEB && skipped[id])) {
        at = s.next(at);  // the rest of a branch the pattern ends, or an ignored module
      } else {
        return false;
      }
    }
  }
  return true;
}

bool match_left_context(const StringView& s, std::size_t pos, const ModuleId* pattern, int n, SkipTable skipped,
                        const unsigned char** params) {
  std::size_t at = pos;
  bool wrapped = false;
  for (int k = n - 1; k >= 0; --k) {
    const ModuleId want = pattern[k];
    while (true) {
      if (at <= s.begin) {
        if (!s.ring || wrapped) return false;
        at = s.end;
        wrapped = true;
      }
      const std::size_t start = s.previous(at);
      const ModuleId id = s.id_at(start);
      if (id == want) {
        params[k] = module_params(s.data, start);
        at = start;
        break;
      }
      if (id == kSB) {
        at = start;  // the start of this branch: the parent lies before it
      } else if (id == kEB) {
        at = skip_branch_backward(s, start);  // a sibling branch, not on the path to the root
      } else if (skipped && skipped[id]) {
        at = start;
      } else {
        return false;
      }
    }
  }
  return true;
}

}  // namespace sylva::derive
