// The interpreter: each module the derivation shows it is decoded into a
// turtle command (by the model's language: lpfg_decoder.h, cpfg_decoder.h),
// which the dispatcher executes at once; the trace, when asked for, writes
// the module and what the command did.
#include "turtle/interpreter.h"

#include <optional>

#include "turtle/command_runner.h"
#include "turtle/cpfg_decoder.h"
#include "turtle/dispatcher.h"
#include "turtle/lpfg_decoder.h"
#include "turtle/trace.h"

namespace sylva::turtle {

struct TurtleInterpreter::Impl {
  Impl(const TurtleSettings& settings, const ModuleTypes& types, geometry::Scene* scene, std::string* trace)
      : cpfg(types.cpfg() ? std::optional<CpfgDecoder>(std::in_place, settings, types) : std::nullopt),
        lpfg(settings),
        turtle(settings, cpfg ? CpfgDecoder::initial_state(settings) : LpfgDecoder::initial_state(settings), scene),
        runner(turtle, trace != nullptr),
        trace(trace) {}

  void visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) {
    turtle.at_module(geometry::Provenance{source_index, id}, in_string);
    if (cpfg ? !cpfg->decode(id, params, source_index, runner) : !lpfg.decode(id, params, runner)) return;
    if (!trace) return;
    if (cpfg) cpfg->append_text(*trace, id, params);
    else LpfgDecoder::append_text(*trace, id, params);
    trace_last();
  }

  // Closes what the string left open.
  void finish() {
    while (turtle.polygon_open()) {
      if (trace) *trace += "end of string: EP";
      if (cpfg) runner(CpfgDecoder::end_polygon());
      else runner(LpfgDecoder::end_polygon());
      trace_last();
    }
    for (int slot = 0; slot < turtle.cylinders().slots(); ++slot) {
      if (!turtle.cylinders().slot_open(slot)) continue;
      if (trace) *trace += "end of string: EndGC";
      runner(command::CloseCylinder{slot});
      trace_last();
    }
  }

  // The rest of the trace's line: what the last command did.
  void trace_last() {
    if (!trace) return;
    append_command(*trace, runner.last(), runner.result(), turtle);
    trace->push_back('\n');
  }

  std::optional<CpfgDecoder> cpfg;  // a cpfg model's; none for L+C
  LpfgDecoder lpfg;
  CommandDispatcher turtle;
  CommandRunner runner;
  std::string* trace;
};

TurtleInterpreter::TurtleInterpreter(const TurtleSettings& settings, const ModuleTypes& types,
                                     geometry::Scene* scene, std::string* trace)
    : impl_(new Impl(settings, types, scene, trace)) {}

TurtleInterpreter::~TurtleInterpreter() { delete impl_; }

void TurtleInterpreter::visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) {
  impl_->visit(id, params, source_index, in_string);
}

void TurtleInterpreter::finish() { impl_->finish(); }

TurtleInterpreter::Pose TurtleInterpreter::pose() const {
  const TurtleState& s = impl_->turtle.state();
  return Pose{s.position, s.frame.heading, s.frame.left, s.frame.up, s.width, s.scale};
}

const derive::ParameterWrites& TurtleInterpreter::query_answers() const { return impl_->turtle.query_answers(); }

geometry::Scene interpret_scene(derive::Derivation& derivation, int view, const TurtleSettings& settings,
                                std::string* trace) {
  geometry::Scene scene;
  TurtleInterpreter turtle(settings, derivation.types(), &scene, trace);
  derivation.interpret(view, turtle);
  turtle.finish();
  return scene;
}

void walk_string(const ModuleString& string, const ModuleTypes& types, const TurtleSettings& settings,
                 geometry::Scene* scene, std::string* trace, derive::ParameterWrites* query_answers) {
  TurtleInterpreter turtle(settings, types, scene, trace);
  const StringView view = string.view(types);
  std::uint32_t index = 0;
  for (std::size_t at = view.begin; at < view.end; at = view.next(at))
    turtle.visit(view.id_at(at), module_params(view.data, at), index++, true);
  turtle.finish();
  if (query_answers) *query_answers = turtle.query_answers();
}

derive::ParameterWrites query_answers(derive::Derivation& derivation, const TurtleSettings& settings) {
  TurtleInterpreter turtle(settings, derivation.types(), nullptr);
  derivation.interpret(0, turtle);
  turtle.finish();
  return turtle.query_answers();
}

}  // namespace sylva::turtle
