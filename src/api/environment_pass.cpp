#include "api/environment_pass.h"

#include <cstdlib>
#include <cstring>

#include "support/diagnostic.h"
#include "sylva/predefined_ids.h"
#include "turtle/interpreter.h"

namespace sylva {
namespace {

// A module's parameters as numbers: a cpfg module's are all floats; an L+C
// module's are read from its printed form, so ints, doubles, vectors and
// structs give their numbers in declaration order.
std::vector<float> parameters_as_floats(const ModuleTypes& types, ModuleId id, const unsigned char* params) {
  std::vector<float> out;
  const ModuleTypes::Type& type = types[id];
  if (types.cpfg()) {
    out.resize(type.param_size / sizeof(float));
    std::memcpy(out.data(), params, out.size() * sizeof(float));
    return out;
  }
  if (type.param_size == 0) return out;
  std::string text;
  types.format_params(id, params, text);
  const char* s = text.c_str();
  while (*s) {
    if ((*s >= '0' && *s <= '9') || *s == '-' || *s == '+' || *s == '.') {
      char* end = nullptr;
      const float v = std::strtof(s, &end);
      if (end != s) {
        out.push_back(v);
        s = end;
        continue;
      }
    }
    ++s;
  }
  return out;
}

// Walks the string with the turtle and notes every communication module.
class QueryCollector : public derive::InterpretedModuleVisitor {
 public:
  QueryCollector(const EnvironmentPass& pass, const env::CommSpec& spec, const turtle::TurtleSettings& settings,
                 const ModuleTypes& types)
      : pass_(pass), spec_(spec), types_(types), turtle_(settings, types, nullptr) {}

  void visit(ModuleId id, unsigned char* params, std::uint32_t source_index, bool in_string) override {
    turtle_.visit(id, params, source_index, in_string);
    // A module made by an interpretation rule is not in the string: its
    // answer would have nowhere to go.
    const int count = pass_.parameter_count(id);
    if (!in_string || count < 0) return;
    env::Query q;
    q.id = source_index;
    q.module.symbol = types_.name(id);
    q.module.parameters.resize(static_cast<std::size_t>(count));
    std::memcpy(q.module.parameters.data(), params, sizeof(float) * static_cast<std::size_t>(count));
    const turtle::TurtleInterpreter::Pose pose = turtle_.pose();
    env::TurtleState& t = q.turtle;
    t.position = {pose.position.x, pose.position.y, pose.position.z};
    t.heading = {pose.heading.x, pose.heading.y, pose.heading.z};
    t.left = {pose.left.x, pose.left.y, pose.left.z};
    t.up = {pose.up.x, pose.up.y, pose.up.z};
    t.line_width = pose.width;
    t.scale_factor = pose.scale;
    t.position_count = spec_.position.count;
    t.heading_count = spec_.heading.count;
    t.left_count = spec_.left.count;
    t.up_count = spec_.up.count;
    t.line_width_count = spec_.line_width.count;
    t.scale_factor_count = spec_.scale_factor.count;
    queries.push_back(std::move(q));
    targets.push_back(Target{id, params, count});
  }

  void finish() { turtle_.finish(); }

  struct Target {
    ModuleId id;
    unsigned char* params;  // in the string
    int count;
  };
  std::vector<env::Query> queries;
  std::vector<Target> targets;

 private:
  const EnvironmentPass& pass_;
  const env::CommSpec& spec_;
  const ModuleTypes& types_;
  turtle::TurtleInterpreter turtle_;
};

}  // namespace

EnvironmentPass::EnvironmentPass(env::CommSpec spec, const ModuleTypes& types, bool clean_ea20,
                                 const std::string& model_file, std::function<void(const std::string&)> verbose)
    : spec_(std::move(spec)), clean_ea20_(clean_ea20), verbose_(std::move(verbose)) {
  counts_.assign(types.size(), -1);
  if (types.cpfg()) {
    for (std::size_t id = 0; id < types.size(); ++id) {
      const ModuleTypes::Type& type = types[static_cast<ModuleId>(id)];
      if (type.name != "?E") continue;
      const int count = static_cast<int>(type.param_size / sizeof(float));
      if (count > env::kMaxParameters)
        throw ModelError(SourceLocation{model_file, 0, 0},
                         "a communication module ?E has " + std::to_string(count) + " parameters; at most " +
                             std::to_string(env::kMaxParameters) + " can be exchanged with the environment");
      counts_[id] = count;
    }
  } else {
    namespace m = rt::mid;
    if (m::E1 < counts_.size()) counts_[m::E1] = 1;
    if (m::E2 < counts_.size()) counts_[m::E2] = 2;
    if (m::EA20 < counts_.size()) counts_[m::EA20] = env::kMaxParameters;
    ea20_ = m::EA20;
  }
}

void EnvironmentPass::run(derive::Derivation& derivation, const turtle::TurtleSettings& settings, env::Field& field) {
  const ModuleTypes& types = derivation.types();
  QueryCollector collector(*this, spec_, settings, types);
  derivation.interpret(collector);
  collector.finish();

  if (spec_.following_module) {
    // The module after each communication module in the string (not after
    // interpretation rules: the string is what the model rewrites).
    const StringView view = derivation.string().view(types);
    for (std::size_t k = 0; k < collector.queries.size(); ++k) {
      const auto& target = collector.targets[k];
      const std::size_t at = static_cast<std::size_t>(target.params - view.data) - sizeof(ModuleId);
      const std::size_t next = view.next(at);
      if (next >= view.end) continue;
      const ModuleId following = view.id_at(next);
      env::ModuleRecord& record = collector.queries[k].following;
      record.symbol = types.name(following);
      record.parameters = parameters_as_floats(types, following, view.data + next + sizeof(ModuleId));
    }
  }

  std::vector<env::Answer> answers(collector.queries.size());
  field.answer(collector.queries, answers, derivation.steps_done());

  int answered = 0;
  for (std::size_t k = 0; k < answers.size(); ++k) {
    const auto& target = collector.targets[k];
    if (clean_ea20_ && target.id == ea20_) std::memset(target.params, 0, sizeof(float) * env::kMaxParameters);
    const env::Answer& answer = answers[k];
    if (answer.set.any()) ++answered;
    for (int i = 0; i < target.count; ++i)
      if (answer.set.test(static_cast<std::size_t>(i)))
        std::memcpy(target.params + sizeof(float) * static_cast<std::size_t>(i), &answer.value[i], sizeof(float));
  }
  if (spec_.verbose && verbose_)
    verbose_("environment: step " + std::to_string(derivation.steps_done()) + ": " +
             std::to_string(collector.queries.size()) + " communication modules, " + std::to_string(answered) +
             " answered\n");
}

}  // namespace sylva
