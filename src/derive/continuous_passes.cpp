// The passes of a differential L-system's continuous time
// (docs/continuous-time.md): the string's continuously changing parameters
// read and written as one state vector, their rates from the derivative
// rules, the event rules' conditions, and the pass that applies the events.
#include <algorithm>
#include <cstring>

#include "derive/derivation.h"

namespace sylva::derive {

using abi::RuleKind;

bool Derivation::has_continuous_rules() const {
  return rules_.has_rules(RuleKind::Derivative) || rules_.has_rules(RuleKind::Event);
}

void Derivation::map_state() {
  state_slots_.clear();
  state_modules_.clear();
  event_modules_.clear();
  const StringView src = string_.view(types_);
  std::size_t largest = 0;
  for (std::size_t pos = src.begin; pos < src.end; pos = src.next(pos)) {
    const ModuleId id = src.id_at(pos);
    if (!rules_.forward(RuleKind::Event, id).empty()) event_modules_.push_back(pos);
    if (rules_.forward(RuleKind::Derivative, id).empty()) continue;
    const std::span<const abi::ParamField> params = types_.params(id);
    largest = std::max(largest, params.size());
    StateModule module{pos, static_cast<std::uint32_t>(state_slots_.size()), 0};
    for (std::uint32_t k = 0; k < params.size(); ++k) {
      const abi::ParamField& p = params[k];
      if (!p.type || (p.type->kind != abi::ParamKind::kFloat && p.type->kind != abi::ParamKind::kDouble)) continue;
      state_slots_.push_back({pos + abi::encoded_id_size(id) + p.offset, k, p.type->kind == abi::ParamKind::kDouble});
      ++module.slots;
    }
    state_modules_.push_back(module);
  }
  rates_.assign(largest, 0.0);
}

void Derivation::gather_state(std::vector<double>& y) {
  map_state();
  y.resize(state_slots_.size());
  const unsigned char* data = string_.data();
  for (std::size_t i = 0; i < state_slots_.size(); ++i) {
    const StateSlot& slot = state_slots_[i];
    if (slot.is_double) {
      std::memcpy(&y[i], data + slot.offset, sizeof(double));
    } else {
      float f;
      std::memcpy(&f, data + slot.offset, sizeof f);
      y[i] = f;
    }
  }
}

void Derivation::scatter_state(double t, std::span<const double> y) {
  control().time = t;
  unsigned char* data = string_.data_for_writing();
  for (std::size_t i = 0; i < state_slots_.size() && i < y.size(); ++i) {
    const StateSlot& slot = state_slots_[i];
    if (slot.is_double) {
      std::memcpy(data + slot.offset, &y[i], sizeof(double));
    } else {
      const float f = static_cast<float>(y[i]);
      std::memcpy(data + slot.offset, &f, sizeof f);
    }
  }
}

void Derivation::evaluate_rates(std::span<double> dy) {
  PassGuard guard(passes_running_);
  std::fill(dy.begin(), dy.end(), 0.0);
  const StringView src = current_view();
  for (const StateModule& module : state_modules_) {
    std::fill(rates_.begin(), rates_.end(), 0.0);
    std::size_t consumed = 0;
    if (!apply_forward(RuleKind::Derivative, src, module.pos, probe_out_, probe_out_, true, &consumed)) continue;
    // Rates are written by parameter index; the state holds the float and
    // double parameters only.
    for (std::uint32_t s = module.first_slot; s < module.first_slot + module.slots; ++s)
      dy[s] = rates_[state_slots_[s].param];
  }
}

void Derivation::read_events(std::vector<continuous::EventReading>& readings) {
  PassGuard guard(passes_running_);
  readings.clear();
  const StringView src = current_view();
  probing_events_ = true;
  struct EndProbe {
    bool& probing;
    ~EndProbe() { probing = false; }
  } end_probe{probing_events_};
  const int group = current_group();
  for (std::size_t pos : event_modules_) {
    // Every event rule of the module is watched, not only the first: the
    // one that fires is the first whose condition holds when one does.
    for (std::uint32_t r : rules_.forward(RuleKind::Event, src.id_at(pos))) {
      const abi::Rule& rule = model_.rules[r];
      if (rule.group != group && rule.group != 0) continue;
      std::size_t consumed = 0;
      if (try_forward(rule, src, pos, probe_out_, probe_out_, true, &consumed)) readings.push_back(event_reading_);
    }
  }
}

std::size_t Derivation::fire_events() {
  std::size_t applied = 0;
  {
    PassGuard guard(passes_running_);
    const StringView src = current_view();
    next_.clear();
    next_.reserve(string_.size_bytes() + 256);
    rewrites_.clear();
    std::size_t pos = src.begin, copied = pos;
    auto flush = [&] {
      if (pos > copied) next_.append(src.data + copied, pos - copied);
    };
    while (pos < src.end) {
      if (rules_.forward(RuleKind::Event, src.id_at(pos)).empty()) {
        pos = src.next(pos);
        continue;
      }
      flush();
      std::size_t consumed = 0;
      const std::size_t output_before = next_.size_bytes();
      if (apply_forward(RuleKind::Event, src, pos, next_, next_, true, &consumed)) {
        note_rewrite(pos, consumed, next_.size_bytes() - output_before);
        pos = consumed;
        ++applied;
      } else {
        const std::size_t n = src.next(pos);
        next_.append(src.data + pos, n - pos);
        pos = n;
      }
      copied = pos;
    }
    flush();
  }
  swap(string_, next_);
  update_births(next_, static_cast<std::uint32_t>(steps_done_));
  decompose();
  map_state();
  return applied;
}

}  // namespace sylva::derive
