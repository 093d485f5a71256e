#include "derive/gillespie.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::derive {

bool is_gillespie_group(const abi::ModelDescriptor& model, int group) {
  const int* groups = model.gillespie_groups;
  return groups && std::find(groups, groups + model.gillespie_group_count, group) != groups + model.gillespie_group_count;
}

double gillespie_uniform(std::uint64_t& state) { return abi::next_erand48(state); }

double gillespie_time(double chi, double total_propensity) {
  if (!(total_propensity > 0)) return std::numeric_limits<double>::infinity();
  return -(1.0 / total_propensity * std::log(1.0 - chi));
}

void ReactionSet::clear() {
  reactions_.clear();
  successors_.clear();
  total_ = 0;
  offers_ = 0;
  warning_.clear();
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
  // lpfg passes a propensity as a float (the parameter of its Propensity module).
  propensity = static_cast<float>(propensity);
  if (!(propensity >= 0) || std::isinf(propensity)) {
    if (self.warning_.empty() && !self.warned_)
      self.warning_ = "a propensity must be a finite number, 0 or more, but this production offers " +
                      std::to_string(propensity) + "; taken as 0, as lpfg takes it";
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

std::string ReactionSet::take_warning() {
  if (warned_ || warning_.empty()) return {};
  warned_ = true;
  return warning_;
}

const ReactionSet::Reaction* ReactionSet::choose(double u) const {
  double rest = total_ * u;
  for (const Reaction& r : reactions_) {
    rest -= r.propensity;
    if (rest <= 0.0) return &r;
  }
  return nullptr;
}

}  // namespace sylva::derive
