#include "derive/derivation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "derive/group_check.h"
#include "derive/in_body_context.h"
#include "derive/keyed_random.h"
#include "lstring/run_limits.h"
#include "support/diagnostic.h"
#include "support/model_faults.h"
#include "sylva/predefined_ids.h"

namespace sylva::derive {
namespace {

using abi::RuleKind;

constexpr int kMaxPattern = 64;

int pattern_length(const abi::Rule& rule) {
  int n = 0;
  for (int part = 0; part < abi::kPatternParts; ++part) n += rule.part_length[part];
  return n;
}

// Rules of the current group first, then group 0's as the fallback (lpfg's
// groups; cpfg's sub-L-systems have no fallback).
template <class TryRule>
bool for_each_group(const std::vector<std::uint32_t>& candidates, const abi::Rule* rules, int group, bool fallback,
                    TryRule&& try_rule) {
  for (std::uint32_t r : candidates)
    if (rules[r].group == group && try_rule(rules[r])) return true;
  if (fallback && group != 0)
    for (std::uint32_t r : candidates)
      if (rules[r].group == 0 && try_rule(rules[r])) return true;
  return false;
}

// Where a call into the model is, for a fault there.
model_faults::CallSite site_of(const abi::Rule& rule, const int* step) {
  static constexpr const char* kKinds[] = {"production", "decomposition rule", "interpretation rule",
                                           "derivative rule", "event"};
  const auto kind = static_cast<std::size_t>(rule.kind);
  return {kind < std::size(kKinds) ? kKinds[kind] : "rule", rule.file, rule.line, step};
}

model_faults::CallSite site_of(const abi::ModelDescriptor& model, const char* statement) {
  return {statement, model.source_file, 0, &model.control->step};
}


}  // namespace

Derivation::Derivation(const abi::ModelDescriptor& model, MessageSink messages)
    : model_(model), types_(ModuleTypes::from_model(model)), rules_(model), messages_(std::move(messages)) {
  model_faults::install_handler();
  for (std::uint32_t r = 0; r < model.rule_count; ++r) {
    if (pattern_length(model.rules[r]) > kMaxPattern)
      throw ModelError(SourceLocation{model.rules[r].file, model.rules[r].line, 0},
                       "a predecessor may have at most " + std::to_string(kMaxPattern) + " modules");
    rule_sites_.push_back(site_of(model.rules[r], &model.control->step));
  }
  for (std::uint32_t f = 0; f < model.filter_count; ++f) {
    const abi::ContextFilter& filter = model.filters[f];
    std::vector<std::uint8_t> skipped(model.module_count, filter.consider ? 1 : 0);
    for (std::uint32_t k = 0; k < filter.count; ++k) skipped[filter.ids[k]] = filter.consider ? 0 : 1;
    // Brackets keep the branching structure, except where cpfg reads a right
    // context past an ignored [ or ] as past any ignored symbol (kFlatBracket).
    const bool cpfg = (model.flags & abi::kModelCpfg) != 0;
    for (ModuleId bracket : {rt::mid::SB, rt::mid::EB})
      skipped[bracket] = cpfg && skipped[bracket] ? kFlatBracket : 0;
    skip_tables_.push_back(std::move(skipped));
  }
  sub_lsystems_ = (model.flags & abi::kModelSubLsystems) != 0;
  lsystems_.assign(1, sub_lsystems_ ? model.main_lsystem : 0);
  uses_query_modules_ = predecessor_holds({rt::mid::GetPos, rt::mid::GetHead, rt::mid::GetLeft, rt::mid::GetUp});
  for (std::uint32_t r = 0; r < model.rule_count; ++r) {
    const abi::Rule& rule = model.rules[r];
    if (rule.kind == RuleKind::Interpretation && rule.view != 0) has_views_ = true;
    if (rule.kind != RuleKind::Production) continue;
    if (rule.part_length[abi::kLeft] || rule.part_length[abi::kRight]) productions_read_context_ = true;
    if (rule.part_length[abi::kNewLeft]) productions_read_new_left_ = true;
    if (rule.part_length[abi::kNewRight]) productions_read_new_right_ = true;
  }
  model_.control->host = this;
  model_.control->message = [](void* self, const char* text) { static_cast<Derivation*>(self)->message(text); };
}

bool Derivation::predecessor_holds(const std::vector<ModuleId>& ids) const {
  for (std::uint32_t r = 0; r < model_.rule_count; ++r) {
    const abi::Rule& rule = model_.rules[r];
    if (rule.kind != RuleKind::Production) continue;
    for (int k = 0; k < pattern_length(rule); ++k)
      if (std::find(ids.begin(), ids.end(), rule.pattern[k]) != ids.end()) return true;
  }
  return false;
}

void Derivation::add_query_modules(const std::vector<ModuleId>& ids) {
  // cpfg interprets the string after every step wherever a query module
  // occurs in the L-system, read by a production or not (its checkEnvironment).
  if (!ids.empty()) uses_query_modules_ = true;
}

Derivation::~Derivation() {
  model_.control->host = nullptr;
  model_.control->message = nullptr;
  release_memory_in_parallel();
}

void Derivation::message(const std::string& text) const {
  if (messages_) messages_(text);
  else std::fputs(text.c_str(), stderr);
}

StringView Derivation::current_view() const {
  StringView v = string_.view(types_);
  v.ring = ring_;
  if (branches_ready_) v.branches = &branches_;
  return v;
}

void Derivation::note_growth(Growth& growth) const {
  // Capped: a step that grew a tiny string into a big one (an axiom that
  // sets up a whole field) says nothing about the next step, and the
  // reservation it would ask for can exceed memory. The buffer grows by
  // itself past the reservation.
  if (string_.size_bytes() == 0) return;
  std::copy_backward(growth.recent.begin(), growth.recent.end() - 1, growth.recent.end());
  growth.recent[0] = std::clamp(static_cast<double>(next_.size_bytes()) / static_cast<double>(string_.size_bytes()),
                                1.0, kMaxGrowthReserved);
}

void Derivation::index_branches() {
  // Below this any branch is cheap to walk.
  constexpr std::size_t kIndexedFrom = std::size_t{64} << 10;
  branches_ready_ = productions_read_context_ && !ring_ && string_.size_bytes() >= kIndexedFrom;
  if (branches_ready_) branches_.prepare(string_.view(types_));
}

SkipTable Derivation::skip_table(const abi::Rule& rule) const {
  return rule.filter < 0 ? nullptr : skip_tables_[static_cast<std::size_t>(rule.filter)].data();
}

// ---- sub-L-systems -------------------------------------------------------------

void Derivation::reset_lsystems() {
  if (sub_lsystems_) lsystems_.assign(1, model_.main_lsystem);
}

void Derivation::track_lsystem(ModuleId id, const unsigned char* params) {
  if (id == model_.call_module) {
    float value;
    std::memcpy(&value, params, sizeof value);
    const int label = static_cast<int>(std::lround(value));
    const int* labels = model_.lsystem_labels;
    if (std::find(labels, labels + model_.lsystem_count, label) == labels + model_.lsystem_count)
      throw ModelError(SourceLocation{model_.source_file, 0, 0},
                       "?(" + std::to_string(label) + ",...) calls L-system " + std::to_string(label) +
                           ", but no 'Lsystem: " + std::to_string(label) + "' is defined");
    lsystems_.push_back(label);
  } else if (id == model_.return_module && lsystems_.size() > 1) {
    lsystems_.pop_back();
  }
}

void Derivation::track_lsystems(const StringView& src, std::size_t from, std::size_t to) {
  for (std::size_t at = from; at < to; at = src.next(at)) track_lsystem(src.id_at(at), module_params(src.data, at));
}

int Derivation::derivation_length() const {
  if (!model_.derivation_length) return 0;
  return model_faults::call_model(site_of(model_, "derivation length"), model_.derivation_length);
}

// ---- control flow ------------------------------------------------------------

void Derivation::start() {
  abi::ControlState& c = control();
  c.forward = true;
  c.stop_requested = false;
  c.step = 0;
  c.current_group = c.next_group = 0;
  c.gillespie_random = abi::kLpfgRandomState;  // every run starts as lpfg's first
  if (c.seed_fixed) c.rand48 = c.gillespie_random = static_cast<std::uint64_t>(c.seed) & 0xFFFFFFFFULL;
  c.gillespie_time = 0;
  c.environment = true;
  steps_done_ = 0;
  string_.clear();
  loaded_in_start_ = false;
  axiom_pending_ = true;
  if (model_.start) model_faults::call_model(site_of(model_, "Start"), model_.start);
}

void Derivation::make_axiom() {
  axiom_pending_ = false;
  ring_ = model_.ring && model_.ring() != 0;
  if (loaded_in_start_) return;  // LoadString in Start: that string, not the axiom
  if (initial_string_) {
    string_.assign(initial_string_->data(), initial_string_->size_bytes());
    reset_births(0);
    return;
  }
  if (!model_.axiom) throw ModelError(SourceLocation{model_.source_file, 0, 0}, "the model has no axiom");
  string_.clear();
  model_faults::call_model(site_of(model_, "the axiom"), [&] { model_.axiom(string_.buffer()); });
  reset_births(0);
  if (!(model_.flags & abi::kModelCpfg)) decompose();  // cpfg does not decompose the axiom
}

void Derivation::set_initial_string(const ModuleString& string) {
  initial_string_.emplace();
  initial_string_->assign(string.data(), string.size_bytes());
}

void Derivation::replace_string(ModuleString string) {
  if (passes_running_ > 0)
    throw ModelError(SourceLocation{model_.source_file, 0, 0},
                     "LoadString may only be called in a control statement (Start, StartEach, EndEach, End), "
                     "not while rules are applied");
  string_ = std::move(string);
  reset_births(static_cast<std::uint32_t>(steps_done_));
  if (axiom_pending_) loaded_in_start_ = true;
}

void Derivation::start_each() {
  abi::ControlState& c = control();
  // lpfg counts the step after the environmental pass, before StartEach:
  // StepNo() is the step's number (from 1) in its StartEach, productions and
  // EndEach.
  c.step = steps_done_ + 1;
  if (model_.start_each) model_faults::call_model(site_of(model_, "StartEach"), model_.start_each);
}

void Derivation::apply_productions() {
  abi::ControlState& c = control();
  const GroupChoice choice = classify_group(model_, c.next_group);
  if (choice != GroupChoice::Defined && warned_groups_.insert(c.next_group).second)
    message(group_warning(model_, c.next_group, choice));
  if (choice == GroupChoice::OutOfRange) c.next_group = c.current_group;
  c.current_group = c.next_group;
  rewrites_.clear();
  {
    PassGuard guard(passes_running_);
    KeyedRandomPass keyed(*this, RuleKind::Production);
    if (choice == GroupChoice::Undeclared) next_.assign(string_.data(), string_.size_bytes());
    else if (is_gillespie_group(model_, c.current_group)) derive_gillespie();
    else {
      index_branches();
      struct Unindex {  // also when the pass throws: the index is of this string only
        Derivation& d;
        ~Unindex() {
          d.branches_needed_ = d.branches_ready_ && d.branches_.built();
          d.branches_ready_ = false;
        }
      } unindex{*this};
      if (c.forward) derive_forward();
      else derive_backward();
    }
  }
  note_growth(growth_);
  swap(string_, next_);
  ++steps_done_;
  c.step = steps_done_;
  update_births(next_, static_cast<std::uint32_t>(steps_done_));
  decompose();
}

void Derivation::end_each() {
  if (model_.end_each) model_faults::call_model(site_of(model_, "EndEach"), model_.end_each);
}

void Derivation::decompose() {
  if (!rules_.has_rules(RuleKind::Decomposition)) return;
  PassGuard guard(passes_running_);
  KeyedRandomPass keyed(*this, RuleKind::Decomposition);
  depth_warnings_.clear();  // warned once per pass, as lpfg does
  next_.clear();
  rewrites_.clear();
  const int depth = maximum_depth(RuleKind::Decomposition);
  reset_lsystems();
  if (!decompose_in_parallel(depth)) expand(RuleKind::Decomposition, current_view(), 0, depth, next_, expansion_);
  note_growth(decomposition_growth_);
  release_deep_expansion();
  swap(string_, next_);
  update_births(next_, static_cast<std::uint32_t>(steps_done_));
}

void Derivation::end() {
  if (model_.end) model_faults::call_model(site_of(model_, "End"), model_.end);
}

void Derivation::run(int steps) {
  begin();
  if (steps < 0) steps = derivation_length();
  for (int k = 0; k < steps && !stop_requested(); ++k) step();
  finish();
}

ModuleString Derivation::interpreted(int view) {
  // The same walk the turtle gets, collected into a string.
  struct Collector : InterpretedModuleVisitor {
    const ModuleTypes& types;
    ModuleString out;
    explicit Collector(const ModuleTypes& t) : types(t) {}
    void visit(ModuleId id, const unsigned char* params, std::uint32_t, bool) override {
      out.append_module(id, params, types[id].param_size);
    }
  } collector(types_);
  collector.out.reserve(string_.size_bytes());
  interpret(view, collector);
  return std::move(collector.out);
}

void Derivation::interpret(int view, InterpretedModuleVisitor& visitor) {
  PassGuard guard(passes_running_);
  KeyedRandomPass keyed(*this, RuleKind::Interpretation);
  struct ViewGuard {
    int& view;
    ~ViewGuard() { view = 0; }
  } view_guard{view_};
  view_ = view;
  const StringView src = current_view();
  const bool has_rules = rules_.has_rules(RuleKind::Interpretation);
  const int depth = has_rules ? maximum_depth(RuleKind::Interpretation) : 1;
  if (has_rules) depth_warnings_.clear();
  while (expansion_.scratch.empty()) expansion_.scratch.emplace_back();
  reset_lsystems();
  std::uint32_t index = 0;
  std::size_t pos = src.begin;
  while (pos < src.end) {
    const ModuleId id = src.id_at(pos);
    if (has_rules && !rules_.forward(RuleKind::Interpretation, id).empty()) {
      ModuleString& successor = expansion_.scratch[0];
      successor.clear();
      std::size_t consumed = 0;
      if (depth < 1) {
        if (apply_forward(RuleKind::Interpretation, src, pos, successor, interpretation_out_, false, &consumed))
          warn_depth_reached(RuleKind::Interpretation, id, depth);
      } else if (apply_forward(RuleKind::Interpretation, src, pos, successor, interpretation_out_, true, &consumed)) {
        interpretation_out_.clear();
        keyed_random::key.level = keyed_random::mix(0, pos);
        expand(RuleKind::Interpretation, successor.view(types_), 1, depth, interpretation_out_, expansion_);
        keyed_random::key.level = 0;
        const StringView shown = interpretation_out_.view(types_);
        for (std::size_t at = shown.begin; at < shown.end; at = shown.next(at))
          visitor.visit(shown.id_at(at), module_params(shown.data, at), index, false);
        for (std::size_t at = pos; at < consumed; at = src.next(at)) ++index;
        pos = consumed;
        continue;
      }
    }
    if (sub_lsystems_) track_lsystem(id, module_params(src.data, pos));
    visitor.visit(id, module_params(src.data, pos), index, true);
    ++index;
    pos = src.next(pos);
  }
  release_deep_expansion();
}

void Derivation::write_parameters(const ParameterWrites& writes) {
  if (passes_running_ > 0) throw std::logic_error("parameters written while rules are applied");
  std::vector<const ParameterWrites::Write*> order;
  order.reserve(writes.writes().size());
  for (const ParameterWrites::Write& w : writes.writes()) order.push_back(&w);
  // Passes give their writes in string order; sorting keeps one walk enough
  // for any order, and keeps writes to one module in the order given.
  std::stable_sort(order.begin(), order.end(),
                   [](const auto* a, const auto* b) { return a->module_index < b->module_index; });
  const StringView view = string_.view(types_);
  unsigned char* data = string_.data_for_writing();
  std::uint32_t index = 0;
  std::size_t pos = view.begin;
  for (const ParameterWrites::Write* w : order) {
    for (; index < w->module_index && pos < view.end; ++index) pos = view.next(pos);
    if (pos >= view.end) throw std::logic_error("a parameter write past the end of the string");
    const std::size_t offset = sizeof(float) * static_cast<std::size_t>(w->first_float);
    const std::size_t bytes = sizeof(float) * static_cast<std::size_t>(w->count);
    if (offset + bytes > types_[view.id_at(pos)].param_size)
      throw std::logic_error("a parameter write past the module's parameters");
    std::memcpy(module_params(data, pos) + offset, writes.values().data() + w->value_offset, bytes);
  }
}

// ---- matching one rule -------------------------------------------------------

bool Derivation::try_forward(const abi::Rule& rule, const StringView& src, std::size_t pos, ModuleString& out,
                             const ModuleString& built, bool call_body, std::size_t* consumed) {
  const int nl = rule.part_length[abi::kNewLeft], l = rule.part_length[abi::kLeft];
  const int s = rule.part_length[abi::kStrict], r = rule.part_length[abi::kRight];
  if (rule.part_length[abi::kNewRight] > 0) return false;  // needs backward derivation
  const unsigned char* params[kMaxPattern];
  const ModuleId* strict = rule.pattern + nl + l;
  std::size_t at = pos;
  for (int k = 0; k < s; ++k) {
    if (at >= src.end || src.id_at(at) != strict[k]) return false;
    params[nl + l + k] = module_params(src.data, at);
    at = src.next(at);
  }
  SkipTable skipped = skip_table(rule);
  // Where each context ends: in-body context tests carry on from there.
  ContextCursor left{pos, false}, right{at, false}, new_left{built.size_bytes(), false};
  if (l && !match_left_context_here(src, left, rule.pattern + nl, l, skipped, params + nl)) return false;
  if (r && !match_right_context_here(src, right, strict + s, r, skipped, params + nl + l + s)) return false;
  const BranchPartners* built_branches = nullptr;
  if (&built == new_branches_of_) built_branches = &new_branches_;
  if (nl) {
    // A view made now: an earlier rule's body may have grown (and moved) the buffer.
    StringView new_string = built.view(types_);
    if (built_branches) {
      new_branches_.catch_up(new_string);
      new_string.branches = built_branches;
    }
    if (!match_left_context(new_string, new_left, rule.pattern, nl, skipped, params)) return false;
  }
  if (!call_body) return true;
  const std::size_t mark = out.size_bytes();
  abi::RuleCall call{out.buffer(), false};
  InBodyContext in_body(src, skipped, left, right);
  if (rule.kind != RuleKind::Interpretation)
    in_body.set_new_left(built, built.size_bytes(), types_.encoded_sizes(), new_left, built_branches);
  in_body.attach(call);
  if (gathering_reactions_) gathering_reactions_->listen(call, pos, at);
  call.rates = rates_.data();
  call.event_probe = probing_events_;
  if (keyed_random_) keyed_random::at_module(pos);
  model_faults::call_model(rule_site(rule), [&] { rule.body(&call, params); });
  // A derivative rule, or an event rule asked for its condition: it applies
  // where it matches, and produces nothing.
  if (rule.kind == RuleKind::Derivative || call.event_probe) {
    event_reading_ = {call.event_holds, call.event_margin};
    out.truncate(mark);
    *consumed = at;
    return true;
  }
  if (!call.produced) {
    out.truncate(mark);  // no produce: the rule did not apply, and nproduce'd modules go
    return false;
  }
  *consumed = at;
  return true;
}

bool Derivation::try_backward(const abi::Rule& rule, const StringView& src, std::size_t end,
                              const StringView& new_string, std::size_t* consumed) {
  const int nl = rule.part_length[abi::kNewLeft], l = rule.part_length[abi::kLeft];
  const int s = rule.part_length[abi::kStrict], r = rule.part_length[abi::kRight];
  const int nr = rule.part_length[abi::kNewRight];
  if (nl > 0) return false;  // needs forward derivation
  const unsigned char* params[kMaxPattern];
  const ModuleId* strict = rule.pattern + l;
  std::size_t at = end;
  for (int k = s - 1; k >= 0; --k) {
    if (at <= src.begin || module_id_before(src.data, at) != strict[k]) return false;
    at = src.previous(at);
    params[l + k] = module_params(src.data, at);
  }
  SkipTable skipped = skip_table(rule);
  // Where each context ends: in-body context tests carry on from there.
  ContextCursor left{at, false}, right{end, false}, new_right{new_string.begin, false};
  if (l && !match_left_context_here(src, left, rule.pattern, l, skipped, params)) return false;
  if (r && !match_right_context_here(src, right, strict + s, r, skipped, params + l + s)) return false;
  if (nr && !match_right_context(new_string, new_right, strict + s + r, nr, skipped, params + l + s + r))
    return false;
  successor_.clear();
  abi::RuleCall call{successor_.buffer(), false};
  InBodyContext in_body(src, skipped, left, right);
  in_body.set_new_right(new_string, new_right);
  in_body.attach(call);
  if (keyed_random_) keyed_random::at_module(end);
  model_faults::call_model(rule_site(rule), [&] { rule.body(&call, params); });
  if (!call.produced) return false;
  *consumed = at;
  return true;
}

bool Derivation::apply_forward(RuleKind kind, const StringView& src, std::size_t pos, ModuleString& out,
                               const ModuleString& built, bool call_body, std::size_t* consumed) {
  const auto& candidates = rules_.forward(kind, src.id_at(pos));
  if (kind != RuleKind::Interpretation || !has_views_)
    return for_each_group(candidates, model_.rules, current_group(), !sub_lsystems_, [&](const abi::Rule& rule) {
      return try_forward(rule, src, pos, out, built, call_body, consumed);
    });
  // Interpretation in views: the view's vgroup first, then the rules outside any vgroup.
  auto in_view = [&](int view) {
    return for_each_group(candidates, model_.rules, current_group(), !sub_lsystems_, [&](const abi::Rule& rule) {
      return rule.view == view && try_forward(rule, src, pos, out, built, call_body, consumed);
    });
  };
  return in_view(view_) || (view_ != 0 && in_view(0));
}

// ---- derivation steps --------------------------------------------------------

void Derivation::derive_forward() {
  if (derive_forward_in_parallel()) return;
  const StringView src = current_view();
  next_.clear();
  // Expect the string to grow as much as in the previous step, so it is
  // allocated once rather than copied on every doubling.
  next_.reserve(affordable_reserve(string_.size_bytes()));
  reset_lsystems();
  struct FollowBrackets {  // of next_ for this pass only, also when it throws
    Derivation& d;
    explicit FollowBrackets(Derivation& derivation) : d(derivation) {
      if (!d.productions_read_new_left_) return;
      d.new_branches_.restart(BuiltBranches::Growth::kAtEnd);
      d.new_branches_of_ = &d.next_;
    }
    ~FollowBrackets() { d.new_branches_of_ = nullptr; }
  } follow(*this);
  forward_range(src, src.begin, src.end, next_);
}

std::size_t Derivation::affordable_reserve(std::size_t source_bytes) const {
  // Near the run's memory limit only what is affordable: the limit is
  // reached by what the step writes, not by what it might.
  const auto expected = static_cast<std::size_t>(static_cast<double>(source_bytes) * growth_.last() * 1.05) + 256;
  const RunBudget* budget = RunBudget::active();
  return budget ? budget->affordable(expected) : expected;
}

std::size_t Derivation::forward_range(const StringView& src, std::size_t from, std::size_t to, ModuleString& out) {
  std::size_t pos = from;
  std::size_t run = pos;  // modules from `run` to `pos` are copied unchanged
  auto flush = [&] {
    if (pos > run) out.append(src.data + run, pos - run);
  };
  const auto before_module = model_.before_module;
  const bool probe = before_module && (model_.flags & abi::kModelProbeProductions) != 0;
  while (pos < to) {
    const ModuleId id = src.id_at(pos);
    const bool cut = id == rt::mid::Cut;
    // cpfg draws for every module of a stochastic L-system, a cut included.
    if (before_module && (probe || !cut)) {
      if (sub_lsystems_) control().current_group = current_group();
      before_module(id);
    }
    if (!cut && rules_.forward(RuleKind::Production, id).empty()) {
      if (sub_lsystems_) track_lsystem(id, module_params(src.data, pos));
      pos = src.next(pos);
      continue;
    }
    flush();
    out.note_module_start(known_start_spacing());
    const std::size_t start = pos;
    if (cut) {
      // Cut drops itself and the rest of its branch; the closing EB stays.
      pos = find_unmatched_end(src, pos);
      note_rewrite(start, pos, 0);
    } else {
      std::size_t consumed = 0;
      if (probe) {
        // The rules that apply tell the model their probabilities; nothing is produced.
        apply_forward(RuleKind::Production, src, pos, probe_out_, out, true, &consumed);
        probe_out_.clear();
        before_module(abi::kNoModule);
      }
      const std::size_t output_before = out.size_bytes();
      if (apply_forward(RuleKind::Production, src, pos, out, out, true, &consumed)) {
        note_rewrite(start, consumed, out.size_bytes() - output_before);
        pos = consumed;
      } else {
        const std::size_t n = src.next(pos);
        out.append(src.data + pos, n - pos);
        pos = n;
      }
    }
    // The L-system of the modules after these: as the old string has it.
    if (sub_lsystems_) track_lsystems(src, start, pos);
    run = pos;
  }
  flush();
  return pos;
}

void Derivation::derive_backward() {
  const StringView src = current_view();
  backward_out_.clear();
  backward_out_.reserve_more(affordable_reserve(string_.size_bytes()));
  std::size_t pos = src.end;
  reset_lsystems();
  const int group = current_group();
  if (productions_read_new_right_) new_branches_.restart(BuiltBranches::Growth::kAtStart);
  // Modules no rule rewrites are copied a run at a time: [pos, kept_until).
  std::size_t kept_until = pos;
  const auto keep_run = [&] {
    backward_out_.prepend(src.data + pos, kept_until - pos);
  };
  while (pos > src.begin) {
    const ModuleId id = module_id_before(src.data, pos);
    std::size_t consumed = 0;
    const auto& candidates = rules_.backward(RuleKind::Production, id);
    bool applied = false;
    if (!candidates.empty()) {
      if (kept_until != pos) {  // a rule may read the new string as right context
        keep_run();
        kept_until = pos;
      }
      StringView built{backward_out_.data(), backward_out_.begin(), backward_out_.end(), types_.encoded_sizes()};
      if (productions_read_new_right_) {
        new_branches_.catch_up(built);
        built.branches = &new_branches_;
      }
      applied = for_each_group(candidates, model_.rules, group, !sub_lsystems_, [&](const abi::Rule& rule) {
        return try_backward(rule, src, pos, built, &consumed);
      });
    }
    if (applied) {
      backward_out_.prepend(successor_.data(), successor_.size_bytes());
      note_rewrite(consumed, pos, successor_.size_bytes());
      pos = kept_until = consumed;
    } else {
      pos = src.previous(pos);
    }
  }
  keep_run();
  next_.take(backward_out_);
  std::reverse(rewrites_.begin(), rewrites_.end());  // noted from the end
}

// ---- decomposition and interpretation -----------------------------------------

std::size_t Derivation::expand(RuleKind kind, const StringView& source, int depth, int max_depth, ModuleString& out,
                               Expansion& expansion, std::size_t stop, std::size_t from) {
  // An explicit stack of the levels being written out rather than recursion,
  // so that a depth of millions needs no machine stack. A level's
  // successors are built in the scratch string of its place on the stack,
  // which stays untouched while the levels below read their own.
  std::vector<ExpansionFrame>& frames = expansion.frames;
  std::deque<ModuleString>& scratch = expansion.scratch;
  frames.clear();
  StringView src = source;
  const std::size_t top_end = std::min(stop, source.end);
  std::size_t pos = from == SIZE_MAX ? src.begin : from;
  std::size_t run = pos;
  auto flush = [&] {
    if (pos > run) out.append(src.data + run, pos - run);
  };
  // Where the current level builds a successor: the scratch string after its source's.
  auto scratch_below = [&] {
    while (scratch.size() <= frames.size() + 1) scratch.emplace_back();
    return &scratch[frames.size() + 1];
  };
  ModuleString* successor = scratch_below();
  // The L-system stack follows the string as it is written out: modules
  // kept as they are here, successors one level down.
  for (;;) {
    if (pos >= (frames.empty() ? top_end : src.end)) {
      flush();
      if (frames.empty()) break;
      // Back to the level above, past the predecessor just expanded.
      const ExpansionFrame up = frames.back();
      frames.pop_back();
      src = up.source;
      depth = up.depth;
      keyed_random::key.level = up.random_level;
      if (depth == 0 && kind == RuleKind::Decomposition)
        note_rewrite(up.pos, up.resume, out.size_bytes() - up.output_before);
      pos = run = up.resume;
      successor = scratch_below();
      continue;
    }
    const ModuleId id = src.id_at(pos);
    if (rules_.forward(kind, id).empty()) {
      if (sub_lsystems_) track_lsystem(id, module_params(src.data, pos));
      pos = src.next(pos);
      continue;
    }
    flush();
    out.note_module_start(known_start_spacing());
    std::size_t consumed = 0;
    if (depth >= max_depth) {
      if (apply_forward(kind, src, pos, *successor, out, false, &consumed)) {
        if (expansion.defer_warnings) expansion.depth_reached.push_back(id);
        else warn_depth_reached(kind, id, max_depth);
      }
    } else {
      successor->clear();
      if (apply_forward(kind, src, pos, *successor, out, true, &consumed)) {
        if (consumed == src.end && !frames.empty()) {
          // The level ends with this successor: it is replaced rather than
          // kept waiting, so a chain of last modules (A --> B A) takes no
          // more memory however deep it goes.
          swap(scratch[frames.size()], *successor);
        } else {
          frames.push_back(ExpansionFrame{src, pos, consumed, out.size_bytes(), depth, keyed_random::key.level});
        }
        keyed_random::key.level = keyed_random::mix(keyed_random::key.level, pos);
        ++depth;
        src = scratch[frames.size()].view(types_);
        pos = run = src.begin;
        successor = scratch_below();
        continue;
      }
    }
    if (sub_lsystems_) track_lsystem(id, module_params(src.data, pos));
    const std::size_t n = src.next(pos);
    out.append(src.data + pos, n - pos);
    pos = run = n;
  }
  return pos;
}

void Derivation::release_deep_expansion() {
  // A pass that went very deep leaves no lasting memory behind.
  constexpr std::size_t kKept = 64;
  if (expansion_.scratch.size() > kKept) expansion_.scratch.resize(kKept);
  if (expansion_.frames.capacity() > kKept) std::vector<ExpansionFrame>().swap(expansion_.frames);
}

int Derivation::maximum_depth(RuleKind kind) const {
  int (*setting)() = kind == RuleKind::Decomposition ? model_.decomposition_depth : model_.interpretation_depth;
  const int depth = setting ? setting() : 1;
  // A number written out is checked where it is written; a computed one here.
  if (depth < 0)
    throw ModelError(SourceLocation{model_.source_file, 0, 0},
                     std::string("the maximum ") + (kind == RuleKind::Decomposition ? "decomposition" : "interpretation") +
                         " depth is negative (" + std::to_string(depth) + "); it must be 0 or more");
  return depth;
}

void Derivation::warn_depth_reached(RuleKind kind, ModuleId id, int max_depth) {
  if (!depth_warnings_.emplace(static_cast<int>(kind), id).second) return;
  message(std::string("warning: maximum ") + (kind == RuleKind::Decomposition ? "decomposition" : "interpretation") +
          " depth (" + std::to_string(max_depth) + ") reached for module " + types_.name(id) + "\n");
}

}  // namespace sylva::derive
