#include "api/simulation.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>
#include <cstdio>

#include "api/derivation_system.h"
#include "api/environment_pass.h"
#include "api/input_queries.h"
#include "api/model_requests.h"
#include "api/outputs.h"
#include "api/views.h"
#include "build/model_library.h"
#include "derive/derivation.h"
#include "env/environment.h"
#include "inputs/input_text.h"
#include "io/output_file.h"
#include "io/string_reader.h"
#include "io/string_text.h"
#include "lang/translator.h"
#include "support/diagnostic.h"
#include "support/repeated_warnings.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/interpreter.h"

namespace sylva {
namespace {

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

std::string file_name(const std::string& file, const char* function, const std::string& model_path) {
  if (file.empty())
    throw ModelError(SourceLocation{model_path, 0, 0},
                     std::string(function) + " needs a file name, and was given none");
  return file;
}

}  // namespace

// ---- opening a model -----------------------------------------------------------

Simulation::Simulation(const std::string& model_path, const SimulationOptions& options, MessageSink user_messages)
    : model_path_(model_path) {
  warnings_ = std::make_shared<RepeatedWarnings>(
      user_messages ? std::move(user_messages) : [](const std::string& text) { std::fputs(text.c_str(), stderr); });
  inputs_ = std::make_unique<io::InputFiles>(io::read_input_files(
      options.input_files, options.build.compiler, view_dialect(model_path, options.build.language)));
  for (const std::string& warning : inputs_->warnings) tell(warning + "\n");
  turtle_settings_ = inputs_->turtle_settings();

  build::BuildOptions build = options.build;
  for (const std::string& define : function_name_defines(*inputs_)) build.defines.push_back(define);
  for (const std::string& define : view_name_defines(*inputs_)) build.defines.push_back(define);
  build::LoadedModel loaded = build::load_model(model_path, build);
  for (const std::string& warning : loaded.built.warnings) tell(warning + "\n");
  compiled_now_ = loaded.built.compiled_now;
  library_ = std::move(loaded.library);

  abi::ControlState& control = *library_->descriptor().control;
  answers_ = std::make_unique<InputAnswers>(*inputs_);
  control.inputs = answers_.get();
  control.input_query = &answer_input_query;
  control.cpfg_window_seeding = options.cpfg_window_seeding;
  control.seed_fixed = options.seed.has_value();
  control.seed = options.seed.value_or(0);
  requests_ = std::make_unique<ModelRequestQueue>();
  control.requests = requests_.get();
  control.request = &ModelRequestQueue::receive;
  derivation_ = std::make_unique<derive::Derivation>(library_->descriptor(),
                                                     [this](const std::string& text) { tell(text); });
  derivation_->set_keyed_random(options.keyed_random);
  derivation_->set_threads(options.threads > 0 ? options.threads
                                               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
                            options.parallel_chunk_bytes ? options.parallel_chunk_bytes
                                                         : derive::Derivation::kMinChunkBytes);
  if (derivation_->types().cpfg()) {
    // A cpfg model's turtle symbols, looked up once for every interpretation;
    // its query symbols (?P ...) are module types of the model's own.
    auto symbols = std::make_shared<const turtle::CpfgSymbols>(derivation_->types());
    derivation_->add_query_modules(symbols->query_modules());
    turtle_settings_.cpfg_symbols = std::move(symbols);
  }
  start_environment(options.environment, options.input_files);
  budget_.set_limits(options.limits);
  budget_.set_module_sizes(derivation_->types().encoded_sizes());
}

Simulation::Simulation(const std::string& model_path, const build::BuildOptions& options, MessageSink messages)
    : Simulation(model_path, SimulationOptions{options, {}}, std::move(messages)) {}

void Simulation::start_environment(const EnvironmentOptions& options, const std::vector<io::InputFile>& input_files) {
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
  for (const std::string& warning : spec.warnings) tell(warning + "\n");
  auto tell_this = [this](const std::string& text) { tell(text); };
  // Made first: a model the environment cannot serve fails before a program is started.
  environment_pass_ =
      std::make_unique<EnvironmentPass>(spec, derivation_->types(), options.clean_ea20, model_path_, tell_this);
  env::FieldOptions field_options;
  field_options.timeout_seconds = options.timeout_seconds;
  field_options.master = derivation_->types().cpfg() ? env::ModelingProgram::cpfg : env::ModelingProgram::lpfg;
  field_options.warn = tell_this;
  field_ = options.field ? options.field : std::shared_ptr<env::Field>(env::make_field(spec, field_options));
}

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

void Simulation::tell(const std::string& text) { (*warnings_)(text); }

const std::vector<std::string>& Simulation::warnings() const { return warnings_->distinct(); }

// ---- the run -------------------------------------------------------------------

void Simulation::begin() {
  if (begun_) return;
  begun_ = true;
  finished_ = false;
  step_seconds_.clear();
  views_.clear();
  pending_frames_.clear();
  display_requested_ = false;
  requests_->clear();
  budget_.start_clock();
  budget_.set_step(0);
  RunBudget::Scope bounded(budget_);
  answers_->restore_curves();  // a run starts from the curves as read, whatever the last run did to them
  derivation_->start();
  act_on_requests(RequestSource::ControlStatement);  // LoadString in Start replaces the axiom
  derivation_->make_axiom();
  if (derivation_->uses_query_modules()) fill_query_modules();
  check_string_limits();
  write_requested_frames(derivation_->stop_requested());
}

bool Simulation::step() {
  begin();
  if (finished_ || stopped()) return false;
  budget_.set_step(derivation_->steps_done() + 1);
  RunBudget::Scope bounded(budget_);
  budget_.check_time();
  const auto started = std::chrono::steady_clock::now();
  // lpfg's Derive and cpfg's Derive both begin with the environmental pass,
  // before StartEach: a run of n steps has n passes, the last one before the
  // last step, so the final string holds what that step produced.
  if (environment_pass_ && derivation_->environment_enabled())
    environment_pass_->run(*derivation_, turtle_settings_, *field_);
  act_on_requests(RequestSource::Rules);  // from interpretation rules the pass ran
  derivation_->start_each();
  act_on_requests(RequestSource::ControlStatement);
  derivation_->apply_productions();
  check_string_limits();
  act_on_requests(RequestSource::Rules);
  if (derivation_->uses_query_modules()) fill_query_modules();
  derivation_->end_each();
  act_on_requests(RequestSource::ControlStatement);
  // Stop() in the same step: lpfg outputs no frame.
  write_requested_frames(derivation_->stop_requested());
  step_seconds_.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return true;
}

void Simulation::finish() {
  if (!begun_ || finished_) return;
  RunBudget::Scope bounded(budget_);
  const bool stopped_before = derivation_->stop_requested();
  derivation_->end();
  finished_ = true;
  act_on_requests(RequestSource::ControlStatement);
  write_requested_frames(!stopped_before && derivation_->stop_requested());
}

void Simulation::run(int steps) {
  const int target = steps >= 0 ? steps : derivation_length();
  if (finished_ && (step_number() == target || stopped())) return;
  if (finished_ || step_number() > target) rewind();
  begin();
  while (step_number() < target && step()) {
  }
  finish();
}

void Simulation::check_string_limits() {
  budget_.check_time();
  budget_.check_modules(derivation_->string().data(), derivation_->string().size_bytes());
}

RunBudget::Scope Simulation::drawing() {
  // Inside another drawing (write's scenes) the string was counted already.
  const bool nested = RunBudget::active() == &budget_;
  budget_.set_step(step_number(), true);
  budget_.check_time();
  if (!nested) budget_.check_drawn_modules(derivation_->string().data(), derivation_->string().size_bytes());
  return RunBudget::Scope(budget_);
}

void Simulation::rewind() {
  begun_ = false;
  finished_ = false;
  continuous_run_.reset();
}

void Simulation::start_from(const ModuleString& string) { derivation_->set_initial_string(string); }

// The query pass: the turtle's state written into the string's query
// modules (GetPos ..., cpfg's ?P ...), as view 0 draws it (LPFG manual 5.12).
void Simulation::fill_query_modules() {
  derivation_->write_parameters(turtle::query_answers(*derivation_, turtle_settings_));
  act_on_requests(RequestSource::Rules);
}

bool Simulation::fills_query_modules() const { return derivation_->uses_query_modules(); }
// Before begin() the derivation still holds the last run's state: a
// rewound run has taken no steps and has not stopped.
bool Simulation::stopped() const { return begun_ && derivation_->stop_requested(); }
int Simulation::step_number() const { return begun_ ? derivation_->steps_done() : 0; }
int Simulation::derivation_length() const { return derivation_->derivation_length(); }
std::string Simulation::parallel_explanation() const { return derivation_->parallel_explanation(); }

// ---- what the model asks for ------------------------------------------------------

void Simulation::act_on_requests(RequestSource source) {
  for (const ModelRequest& r : requests_->take()) act_on_request(r.kind, r.value, r.file, source);
}

void Simulation::act_on_request(int request, int value, const std::string& file, RequestSource source) {
  switch (request) {
    case abi::kRequestOutputString:
      write_string(file_name(file, "OutputString", model_path_));
      break;
    case abi::kRequestLoadString:
      if (source == RequestSource::Rules)
        throw ModelError(SourceLocation{model_path_, 0, 0},
                         "LoadString may only be called in a control statement (Start, StartEach, EndEach, End), "
                         "not while rules are applied");
      derivation_->replace_string(io::read_string_file(file_name(file, "LoadString", model_path_), types()));
      break;
    case abi::kRequestOutputFrame: {
      std::string path = file_name(file, "OutputFrame", model_path_);
      check_output_path(path);
      pending_frames_.push_back(std::move(path));
      break;
    }
    case abi::kRequestDisplayFrame:
      display_requested_ = true;
      break;
    case abi::kRequestUseView:
      check_view(value, *inputs_, model_path_);
      if (std::find(views_.begin(), views_.end(), value) == views_.end()) {
        views_.push_back(value);
        std::sort(views_.begin(), views_.end());
      }
      break;
    default:
      break;
  }
}

void Simulation::write_requested_frames(bool stopped) {
  std::vector<std::string> frames;
  frames.swap(pending_frames_);
  if (!stopped) write(frames);
}

bool Simulation::take_display_request() {
  const bool requested = display_requested_;
  display_requested_ = false;
  return requested;
}

// ---- what the string is ------------------------------------------------------------

const ModuleString& Simulation::string() const { return derivation_->string(); }

std::string Simulation::string_text() const { return io::format_string(derivation_->string(), types()); }

void Simulation::write_string(const std::string& path) const {
  io::write_output_file(path, [this](const ContentSink& sink) { io::write_string_text(string(), types(), sink); });
}

void Simulation::track_births(bool on) { derivation_->track_births(on); }
const std::vector<std::uint32_t>& Simulation::birth_steps() const { return derivation_->births(); }

ModuleString Simulation::interpreted(int view) {
  const RunBudget::Scope bounded = drawing();
  ModuleString result = derivation_->interpreted(view);
  act_on_requests(RequestSource::Rules);
  return result;
}

std::string Simulation::interpreted_text(int view) { return io::format_string(interpreted(view), types()); }

void Simulation::write_interpreted_string(const std::string& path, int view) {
  const ModuleString text = interpreted(view);
  io::write_output_file(path, [&](const ContentSink& sink) { io::write_string_text(text, types(), sink); });
}

geometry::Scene Simulation::scene(int view) {
  const RunBudget::Scope bounded = drawing();
  geometry::Scene drawn = turtle::interpret_scene(*derivation_, view, turtle_settings_);
  act_on_requests(RequestSource::Rules);
  return drawn;
}

std::string Simulation::turtle_trace(int view) {
  const RunBudget::Scope bounded = drawing();
  std::string trace;
  turtle::interpret_scene(*derivation_, view, turtle_settings_, &trace);
  act_on_requests(RequestSource::Rules);
  return trace;
}

void Simulation::write(const std::vector<std::string>& paths) {
  if (paths.empty()) return;
  const RunBudget::Scope bounded = drawing();
  std::map<int, geometry::Scene> scenes;  // by view
  for (const std::string& path : paths)
    for (const ViewOutput& out : view_outputs(path, *this, output_options_)) {
      auto drawn = scenes.find(out.view);
      if (drawn == scenes.end()) drawn = scenes.emplace(out.view, scene(out.view)).first;
      write_output(out.path, drawn->second, *this, out.size, out.view);
    }
}

const ModuleTypes& Simulation::types() const { return derivation_->types(); }
const abi::ModelDescriptor& Simulation::descriptor() const { return library_->descriptor(); }

}  // namespace sylva
