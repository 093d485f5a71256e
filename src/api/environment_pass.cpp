#include "api/environment_pass.h"

#include <algorithm>
#include <cstring>

#include "support/diagnostic.h"
#include "sylva/predefined_ids.h"
#include "turtle/interpreter.h"

namespace sylva {
namespace {

// A module's parameters as numbers, in declaration order: ints, doubles,
// vectors and structs give theirs as floats.
std::vector<float> parameters_as_floats(const ModuleTypes& types, ModuleId id, const unsigned char* params) {
  const std::vector<double> numbers = types.numbers(id, params);
  return std::vector<float>(numbers.begin(), numbers.end());
}

// Walks the string with the turtle, as lpfg and cpfg do in their
// environmental pass, and notes every communication module the turtle meets:
//  - a module of the string, interpreted as itself: sent, and answered in the
//    string;
//  - a module an interpretation rule replaces is not met, so not sent;
//  - a module an interpretation rule produces is sent (the program sees it)
//    but its answer has nowhere to go: cpfg drops it, and Sylva does the same
//    for lpfg, whose answer would land on whatever module of the string has
//    the produced module's place in the rule's successor.
class QueryCollector : public derive::InterpretedModuleVisitor {
 public:
  QueryCollector(const EnvironmentPass& pass, const env::CommSpec& spec, const turtle::TurtleSettings& settings,
                 const ModuleTypes& types)
      : pass_(pass), spec_(spec), types_(types), turtle_(settings, types, nullptr) {}

  void visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) override {
    const int count = pass_.parameter_count(id);
    if (count >= 0) note(id, params, count, source_index, in_string);
    turtle_.visit(id, params, source_index, in_string);
  }

  void finish() { turtle_.finish(); }

  struct Target {
    ModuleId id;
    const unsigned char* params;  // in the string; null for a module a rule produced
    std::uint32_t index;          // in the string
    int count;
  };
  std::vector<env::Query> queries;
  std::vector<Target> targets;

 private:
  void note(ModuleId id, const unsigned char* params, int count, std::uint32_t place, bool in_string) {
    env::Query q;
    q.id = place;
    q.module.symbol = types_.name(id);
    q.module.parameters.resize(static_cast<std::size_t>(count));
    std::memcpy(q.module.parameters.data(), params, sizeof(float) * static_cast<std::size_t>(count));
    q.turtle = turtle_report();
    queries.push_back(std::move(q));
    targets.push_back(Target{id, in_string ? params : nullptr, place, count});
  }

  env::TurtleReport turtle_report() const {
    const turtle::TurtleInterpreter::Pose pose = turtle_.pose();
    env::TurtleReport t;
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
    return t;
  }

  const EnvironmentPass& pass_;
  const env::CommSpec& spec_;
  const ModuleTypes& types_;
  turtle::TurtleInterpreter turtle_;
};

}  // namespace

EnvironmentPass::EnvironmentPass(env::CommSpec spec, const ModuleTypes& types, bool clean_ea20,
                                 const std::string& model_file, std::function<void(const std::string&)> verbose)
    : spec_(std::move(spec)), clean_ea20_(clean_ea20), model_file_(model_file), verbose_(std::move(verbose)) {
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
  const StringView view = derivation.string().view(types);
  QueryCollector collector(*this, spec_, settings, types);
  derivation.interpret(0, collector);
  collector.finish();

  if (spec_.following_module) {
    // The module after each communication module in the string (not after
    // interpretation rules: the string is what the model rewrites).
    for (std::size_t k = 0; k < collector.queries.size(); ++k) {
      const auto& target = collector.targets[k];
      if (!target.params) continue;  // produced by a rule: its neighbours are not the string's
      const std::size_t at = static_cast<std::size_t>(target.params - view.data) - abi::encoded_id_size(target.id);
      const std::size_t next = view.next(at);
      if (next >= view.end) continue;
      const ModuleId following = view.id_at(next);
      env::ModuleRecord& record = collector.queries[k].following;
      record.symbol = types.name(following);
      record.parameters = parameters_as_floats(types, following, module_params(view.data, next));
    }
  }

  std::vector<env::Answer> answers(collector.queries.size());
  const int step = derivation.steps_done();
  field.answer(collector.queries, answers, step);

  int answered = 0;
  derive::ParameterWrites writes;
  for (std::size_t k = 0; k < answers.size(); ++k) {
    const auto& target = collector.targets[k];
    const env::Answer& answer = answers[k];
    check_answer(collector.queries[k], answer, step);
    if (!target.params || !answer.set.any()) continue;  // produced by an interpretation rule: nowhere to write
    ++answered;
    float values[env::kMaxParameters];
    std::memcpy(values, target.params, sizeof(float) * static_cast<std::size_t>(target.count));
    // lpfg zeroes an EA20 when an answer for it arrives (-cleanEA20).
    if (clean_ea20_ && target.id == ea20_) std::fill(values, values + target.count, 0.0f);
    for (int i = 0; i < target.count; ++i)
      if (answer.set.test(static_cast<std::size_t>(i))) values[i] = answer.value[i];
    writes.set_floats(target.index, 0, values, target.count);
  }
  derivation.write_parameters(writes);
  if (spec_.verbose && verbose_)
    verbose_("environment: pass before step " + std::to_string(step + 1) + ": " +
             std::to_string(collector.queries.size()) +
             " communication modules, " + std::to_string(answered) + " answered\n");
}

// An answer for a parameter the module lacks is the environment's mistake;
// dropping it would hide the mistake from whoever wrote the program.
void EnvironmentPass::check_answer(const env::Query& query, const env::Answer& answer, int step) const {
  const std::size_t count = query.module.parameters.size();
  for (std::size_t i = count; i < answer.set.size(); ++i) {
    if (!answer.set.test(i)) continue;
    throw ModelError(answerer_location(), answerer() + " answered parameter " + std::to_string(i) + " of module " +
                                              std::to_string(query.id) + " (" + query.module.symbol +
                                              "), which has " + std::to_string(count) +
                                              (count == 1 ? " parameter" : " parameters") +
                                              ", during the environmental pass before step " + std::to_string(step + 1));
  }
}

// The program on the .e file's executable: line, or the embedding program's
// field when there is no .e file.
std::string EnvironmentPass::answerer() const {
  if (spec_.executable.empty()) return "the environment";
  const std::size_t start = spec_.executable.find_first_not_of(" \t");
  const std::size_t end = spec_.executable.find_first_of(" \t", start);
  return "environmental program '" + spec_.executable.substr(start, end - start) + "'";
}

SourceLocation EnvironmentPass::answerer_location() const {
  if (spec_.path.empty()) return SourceLocation{model_file_, 0, 0};
  return SourceLocation{spec_.path, spec_.executable_line, 0};
}

}  // namespace sylva
