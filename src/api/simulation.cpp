#include "api/simulation.h"

#include <cstdio>

#include "api/environment_pass.h"
#include "api/input_queries.h"
#include "api/model_requests.h"
#include "api/views.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/interpreter.h"
#include "env/environment.h"
#include "inputs/input_text.h"
#include "lang/translator.h"
#include "support/diagnostic.h"
#include "support/repeated_warnings.h"

namespace sylva {
namespace {

// A message for the user: to the sink, or to standard error without one.
void tell(const derive::Derivation::MessageSink& messages, const std::string& text) {
  if (messages) messages(text);
  else std::fputs(text.c_str(), stderr);
}

// A model's view file is read as its program reads it: a cpfg model's as
// cpfg does, an L+C model's as lpfg does.
io::ViewDialect view_dialect(const std::string& model_path, const std::string& language) {
  if (language == "cpfg") return io::ViewDialect::Cpfg;
  if (language == "lc") return io::ViewDialect::Lpfg;
  try {
    return lang::looks_like_cpfg(io::read_input_file(model_path, "model")) ? io::ViewDialect::Cpfg
                                                                             : io::ViewDialect::Lpfg;
  } catch (const ModelError&) {
    return io::ViewDialect::Lpfg;  // the build says what is wrong with the model file
  }
}

}  // namespace

void Simulation::start_environment(const EnvironmentOptions& options, const std::vector<io::InputFile>& input_files,
                                   const derive::Derivation::MessageSink& messages) {
  std::string comm_file = options.comm_file;
  for (const io::InputFile& file : input_files) {
    if (file.kind != io::InputKind::Environment) continue;
    const std::string& path = file.path;
    if (!comm_file.empty() && comm_file != path)
      throw ModelError(SourceLocation{path, 0, 0}, "a second communication specification file (the first is " +
                                                       comm_file + "); a model talks to one environment");
    comm_file = path;
  }
  if (comm_file.empty() && !options.field) return;
  env::CommSpec spec = comm_file.empty() ? env::CommSpec::everything() : env::read_comm_spec(comm_file);
  for (const std::string& warning : spec.warnings) tell(messages, warning + "\n");
  auto verbose = [messages](const std::string& text) { tell(messages, text); };
  // Made first: a model the environment cannot serve fails before a program is started.
  environment_pass_ = std::make_unique<EnvironmentPass>(spec, derivation_->types(), options.clean_ea20, model_path_,
                                                        std::move(verbose));
  env::FieldOptions field_options;
  field_options.timeout_seconds = options.timeout_seconds;
  field_options.master = derivation_->types().cpfg() ? env::ModelingProgram::cpfg : env::ModelingProgram::lpfg;
  field_options.warn = [messages](const std::string& text) { tell(messages, text); };
  field_ = options.field ? options.field : std::shared_ptr<env::Field>(env::make_field(spec, field_options));
  derivation_->set_environment_pass(
      [this](derive::Derivation& d) { environment_pass_->run(d, turtle_settings_, *field_); });
}

Simulation::Simulation(const std::string& model_path, const SimulationOptions& options,
                       derive::Derivation::MessageSink user_messages)
    : model_path_(model_path) {
  warnings_ = std::make_shared<RepeatedWarnings>(
      user_messages ? std::move(user_messages) : [](const std::string& text) { std::fputs(text.c_str(), stderr); });
  derive::Derivation::MessageSink messages = [warnings = warnings_](const std::string& text) { (*warnings)(text); };
  inputs_ = std::make_unique<io::InputFiles>(io::read_input_files(
      options.input_files, options.build.compiler, view_dialect(model_path, options.build.language)));
  for (const std::string& warning : inputs_->warnings) tell(messages, warning + "\n");
  turtle_settings_ = inputs_->turtle_settings();

  build::BuildOptions build = options.build;
  for (const std::string& define : function_name_defines(*inputs_)) build.defines.push_back(define);
  for (const std::string& define : view_name_defines(*inputs_)) build.defines.push_back(define);
  build::BuiltModel built = build::build_model(model_path, build);
  for (const std::string& warning : built.warnings) tell(messages, warning + "\n");
  compiled_now_ = built.compiled_now;
  library_ = std::make_unique<build::ModelLibrary>(built.library_path);

  abi::ControlState& control = *library_->descriptor().control;
  answers_ = std::make_unique<InputAnswers>(*inputs_);
  control.inputs = answers_.get();
  control.input_query = &answer_input_query;
  control.cpfg_window_seeding = options.cpfg_window_seeding;
  const derive::Derivation::MessageSink environment_messages = messages;
  derivation_ = std::make_unique<derive::Derivation>(library_->descriptor(), std::move(messages));
  if (derivation_->types().cpfg()) {
    // A cpfg model's turtle symbols, looked up once for every interpretation;
    // its query symbols (?P ...) are module types of the model's own.
    auto symbols = std::make_shared<const turtle::CpfgSymbols>(derivation_->types());
    derivation_->add_query_modules(symbols->query_modules());
    turtle_settings_.cpfg_symbols = std::move(symbols);
  }
  requests_ = std::make_unique<ModelRequests>(*this);
  control.requests = requests_.get();
  control.request = &ModelRequests::handle;
  derivation_->set_phase_hook(
      [this](derive::Derivation::Phase phase, bool stopped) {
        // A run starts from the curves as read, whatever the last run did to them.
        if (phase == derive::Derivation::Phase::Starting) answers_->restore_curves();
        requests_->on_phase(phase, stopped);
      });
  derivation_->set_query_pass(
      [this](derive::Derivation& d) { turtle::fill_query_modules(d, turtle_settings_); });
  start_environment(options.environment, options.input_files, environment_messages);
}

Simulation::Simulation(const std::string& model_path, const build::BuildOptions& options,
                       derive::Derivation::MessageSink messages)
    : Simulation(model_path, SimulationOptions{options, {}}, std::move(messages)) {}

Simulation::~Simulation() {
  warnings_->finish();
  if (field_) {
    try {
      field_->finish();
    } catch (...) {
      // The run is over; a program that fails to exit cleanly was killed.
    }
  }
  if (library_) {
    abi::ControlState& control = *library_->descriptor().control;
    control.inputs = nullptr;
    control.input_query = nullptr;
    control.requests = nullptr;
    control.request = nullptr;
  }
}

geometry::Scene Simulation::scene(std::string* trace) { return scene(primary_view(), trace); }

geometry::Scene Simulation::scene(int view, std::string* trace) {
  derivation_->set_view(view);
  geometry::Scene result = turtle::interpret_scene(*derivation_, turtle_settings_, trace);
  derivation_->set_view(0);  // the query pass uses view 0's rules (LPFG manual 5.12)
  return result;
}

const std::vector<int>& Simulation::views() const { return requests_->views(); }

void Simulation::set_output_options(const OutputOptions& options) { requests_->options = options; }

bool Simulation::take_display_request() { return requests_->take_display_request(); }

}  // namespace sylva
