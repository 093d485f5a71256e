#include "lstring/built_branches.h"

#include <algorithm>

#include "sylva/predefined_ids.h"

namespace sylva {

void BuiltBranches::restart(Growth growth) {
  growth_ = growth;
  seen_ = end_ = 0;
  forgot_ = false;
  open_.clear();
  pairs_.clear();
}

void BuiltBranches::catch_up(const StringView& built) {
  constexpr ModuleId kSB = rt::mid::SB;
  constexpr ModuleId kEB = rt::mid::EB;
  end_ = built.end;
  if (growth_ == Growth::kAtEnd) {
    // Appended: an SB waits for the EB that comes after it.
    for (std::size_t at = seen_; at < built.end; at = built.next(at)) {
      const ModuleId id = built.id_at(at);
      if (id == kSB) {
        open_.push_back(at);
      } else if (id == kEB && !open_.empty()) {
        add_pair(at, open_.back());
        open_.pop_back();
      }
    }
    seen_ = built.end;
    return;
  }
  // Prepended: read from the old start toward the new one, an EB waits for
  // the SB that comes before it.
  for (std::size_t at = built.end - seen_; at > built.begin;) {
    at = built.previous(at);
    const ModuleId id = built.id_at(at);
    if (id == kEB) {
      open_.push_back(built.end - at);
    } else if (id == kSB && !open_.empty()) {
      add_pair(built.end - at, open_.back());
      open_.pop_back();
    }
  }
  seen_ = built.end - built.begin;
}

void BuiltBranches::add_pair(std::size_t key, std::size_t partner_key) {
  if (pairs_.size() == 2 * kRecentPairs) {
    pairs_.erase(pairs_.begin(), pairs_.begin() + kRecentPairs);
    forgot_ = true;
  }
  pairs_.emplace_back(key, partner_key);
}

std::size_t BuiltBranches::partner_of(std::size_t key) const {
  if (forgot_ && (pairs_.empty() || key < pairs_.front().first)) return kUnknown;
  const auto found = std::lower_bound(pairs_.begin(), pairs_.end(), key,
                                      [](const std::pair<std::size_t, std::size_t>& p, std::size_t k) { return p.first < k; });
  return found != pairs_.end() && found->first == key ? found->second : kUnmatched;
}

std::size_t BuiltBranches::sb_of(std::size_t eb) const {
  if (growth_ != Growth::kAtEnd || eb >= seen_) return kUnknown;
  return partner_of(eb);
}

std::size_t BuiltBranches::eb_of(std::size_t sb) const {
  if (growth_ != Growth::kAtStart || sb > end_ || end_ - sb > seen_) return kUnknown;
  const std::size_t eb = partner_of(end_ - sb);
  return eb == kUnmatched || eb == kUnknown ? eb : end_ - eb;
}

}  // namespace sylva
