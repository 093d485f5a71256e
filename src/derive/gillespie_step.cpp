// A derivation step using a Gillespie group (LPFG manual 7.2); see gillespie.h.
#include "derive/derivation.h"
#include "support/diagnostic.h"

namespace sylva::derive {

void Derivation::derive_gillespie() {
  abi::ControlState& c = control();
  const int group = c.current_group;
  // Ring L-systems are ignored in Gillespie steps (7.2): the string has two
  // ends. Forward() and Backward() change nothing: one module is rewritten.
  const StringView src = string_.view(types_);

  // As lpfg gathers them: every production of the group that matches a
  // module offers its reactions, in order, until one that matches offers
  // none, which ends the module's offers. Productions outside the group
  // (group 0's included) take no part.
  reactions_.clear();
  struct Gathering {
    ReactionSet*& target;
    ~Gathering() { target = nullptr; }
  } gathering{gathering_reactions_};
  gathering_reactions_ = &reactions_;
  for (std::size_t pos = src.begin; pos < src.end; pos = src.next(pos)) {
    for (std::uint32_t r : rules_.forward(abi::RuleKind::Production, src.id_at(pos))) {
      const abi::Rule& rule = model_.rules[r];
      if (rule.group != group) continue;
      reaction_scratch_.clear();
      std::size_t consumed = 0;
      if (!try_forward(rule, src, pos, reaction_scratch_, reaction_scratch_, false, &consumed)) continue;
      const std::size_t offers_before = reactions_.offers();
      try_forward(rule, src, pos, reaction_scratch_, reaction_scratch_, true, &consumed);
      if (const std::string warning = reactions_.take_warning(); !warning.empty())
        message(std::string(rule.file) + ":" + std::to_string(rule.line) + ": warning: " + warning +
                " (Gillespie group " + std::to_string(group) + ")\n");
      if (reactions_.offers() == offers_before) break;
    }
  }
  gathering_reactions_ = nullptr;

  next_.clear();
  if (!string_.empty()) next_.assign(string_.data(), string_.size_bytes());
  // No reaction can fire, now or ever: the string and the clock stay.
  if (reactions_.empty()) return;
  // lpfg's order: the first number chooses the reaction, the second gives the
  // time to it, which GillespieTime() adds up.
  const ReactionSet::Reaction* fired = reactions_.choose(gillespie_uniform(c.gillespie_random));
  c.gillespie_time += gillespie_time(gillespie_uniform(c.gillespie_random), reactions_.total_propensity());
  if (!fired) return;
  next_.clear();
  auto copy = [this](const unsigned char* bytes, std::size_t n) {
    if (n > 0) next_.append(bytes, n);
  };
  note_rewrite(fired->begin, fired->end, fired->successor_end - fired->successor_begin);
  copy(src.data + src.begin, fired->begin - src.begin);
  copy(reactions_.successors() + fired->successor_begin, fired->successor_end - fired->successor_begin);
  copy(src.data + fired->end, src.end - fired->end);
}

}  // namespace sylva::derive
