#include "derive/gillespie.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::derive {

bool is_gillespie_group(const abi::ModelDescriptor& model, int group) {
  const int* groups = model.gillespie_groups;
  return groups && std::find(groups, groups + model.gillespie_group_count, group) != groups + model.gillespie_group_count;
}

double gillespie_uniform(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double gillespie_time(double chi, double total_propensity) {
  if (!(total_propensity > 0)) return std::numeric_limits<double>::infinity();
  return -std::log1p(-chi) / total_propensity;
}

void ReactionSet::clear() {
  reactions_.clear();
  successors_.clear();
  total_ = 0;
  offers_ = 0;
  error_.clear();
}

void ReactionSet::listen(abi::RuleCall& call, std::size_t begin, std::size_t end) {
  call.reactions = this;
  call.propose = &ReactionSet::propose;
  begin_ = begin;
  end_ = end;
  body_start_ = call.out->size;
}

void ReactionSet::propose(abi::RuleCall* call, double propensity) {
  ReactionSet& self = *static_cast<ReactionSet*>(call->reactions);
  ++self.offers_;
  if (!(propensity >= 0) || std::isinf(propensity)) {
    if (self.error_.empty())
      self.error_ = "a propensity must be a finite number, 0 or more, but this production offers " +
                    std::to_string(propensity);
    return;
  }
  if (propensity == 0) return;  // a reaction that cannot happen now
  // The successor: what the body has written since it began (nproduce'd
  // modules, then the reaction's own).
  const std::size_t from = self.successors_.size();
  self.successors_.insert(self.successors_.end(), call->out->data + self.body_start_, call->out->data + call->out->size);
  self.reactions_.push_back(Reaction{propensity, self.begin_, self.end_, from, self.successors_.size()});
  self.total_ += propensity;
}

const ReactionSet::Reaction& ReactionSet::choose(double u) const {
  const double target = u * total_;
  double cumulative = 0;
  for (const Reaction& r : reactions_) {
    cumulative += r.propensity;
    if (target < cumulative) return r;
  }
  return reactions_.back();  // u * P rounded up to P
}

}  // namespace sylva::derive
