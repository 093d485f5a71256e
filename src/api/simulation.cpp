#include "api/simulation.h"

#include <cstdio>

#include "api/input_queries.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/interpreter.h"

namespace sylva {

Simulation::Simulation(const std::string& model_path, const SimulationOptions& options,
                       derive::Derivation::MessageSink messages) {
  inputs_ = std::make_unique<io::InputFiles>(io::read_input_files(options.input_files, options.build.compiler));
  for (const std::string& warning : inputs_->warnings) {
    if (messages) messages(warning + "\n");
    else std::fprintf(stderr, "%s\n", warning.c_str());
  }
  turtle_settings_ = inputs_->turtle_settings();

  build::BuildOptions build = options.build;
  for (const std::string& define : function_name_defines(*inputs_)) build.defines.push_back(define);
  build::BuiltModel built = build::build_model(model_path, build);
  compiled_now_ = built.compiled_now;
  library_ = std::make_unique<build::ModelLibrary>(built.library_path);

  abi::ControlState& control = *library_->descriptor().control;
  answers_ = std::make_unique<InputAnswers>(*inputs_);
  control.inputs = answers_.get();
  control.input_query = &answer_input_query;
  derivation_ = std::make_unique<derive::Derivation>(library_->descriptor(), std::move(messages));
  if (derivation_->types().cpfg()) {
    // A cpfg model's turtle symbols, looked up once for every interpretation;
    // its query symbols (?P ...) are module types of the model's own.
    auto symbols = std::make_shared<const turtle::CpfgSymbols>(derivation_->types());
    derivation_->add_query_modules(symbols->query_modules());
    turtle_settings_.cpfg_symbols = std::move(symbols);
  }
  derivation_->set_query_pass(
      [this](derive::Derivation& d) { turtle::fill_query_modules(d, turtle_settings_); });
}

Simulation::Simulation(const std::string& model_path, const build::BuildOptions& options,
                       derive::Derivation::MessageSink messages)
    : Simulation(model_path, SimulationOptions{options, {}}, std::move(messages)) {}

Simulation::~Simulation() {
  if (library_) {
    abi::ControlState& control = *library_->descriptor().control;
    control.inputs = nullptr;
    control.input_query = nullptr;
  }
}

geometry::Scene Simulation::scene(std::string* trace) {
  return turtle::interpret_scene(*derivation_, turtle_settings_, trace);
}

}  // namespace sylva
