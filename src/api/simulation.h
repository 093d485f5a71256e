// The public entry point of the engine: a model file and its input files,
// built (or taken from the cache), loaded, and ready to step, to be drawn and
// to be written. Front doors (the command line, the studio, tests) go through
// here and nowhere else.
//
// A run, as Simulation::step and its neighbours carry it out (LPFG manual
// ch. 6; EnviroManual 1.4):
//   begin:  Start, the axiom (or a saved string) and its decomposition,
//           query modules filled;
//   step:   the environmental pass, StartEach, productions, decomposition,
//           query modules filled, EndEach, the frames the model asked for;
//   finish: End.
// What the model asks for from its control statements (OutputString,
// LoadString, OutputFrame, DisplayFrame, UseView) is queued while they run
// and acted on as each returns.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "build/model_builder.h"
#include "continuous/continuous_run.h"
#include "env/field.h"
#include "geometry/scene.h"
#include "inputs/input_files.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "lstring/run_limits.h"
#include "sylva/abi.h"
#include "turtle/turtle_settings.h"

namespace sylva {

namespace build {
class ModelLibrary;
}
namespace derive {
class Derivation;
}
class InputAnswers;
class RepeatedWarnings;
class EnvironmentPass;
class ModelRequestQueue;

// Open L-systems: the environment the model's communication modules (E1,
// E2, EA20, cpfg's ?E) talk to before every step. See docs/environment.md.
struct EnvironmentOptions {
  // The communication specification file (.e): the program to run and what
  // to send it. A .e file among SimulationOptions::input_files is taken too.
  std::string comm_file;
  // An environment of the embedding program's own: answers the queries
  // instead of the .e file's executable (which is then not started). With no
  // .e file every turtle field and the following module are sent.
  std::shared_ptr<env::Field> field;
  // How long an external program may take over one pass.
  double timeout_seconds = 60;
  // lpfg's -cleanEA20: EA20's values are zeroed before answers are written.
  bool clean_ea20 = false;
};

struct SimulationOptions {
  build::BuildOptions build;
  // View, animation, colormap, material, contour, function and environment
  // files, in the order given (lpfg's command line): ids of contours and
  // functions follow it. A path alone is recognised by its extension.
  std::vector<io::InputFile> input_files;
  EnvironmentOptions environment = {};
  // cpfg models: choose among stochastic productions from seed: as cpfg's
  // window does. cpfg in batch (-g) ignores seed: and so, by default, does
  // Sylva, whose runs give cpfg's batch strings.
  bool cpfg_window_seeding = false;
  // How many modules, how much string memory and how much time the run may
  // take (lstring/run_limits.h); past one the run stops with LimitExceeded.
  RunLimits limits = default_run_limits();
  // Threads a derivation pass may use where the result cannot differ from a
  // serial pass's (docs/parallel-derivation.md); 0: one per core.
  int threads = 0;
  // The least bytes of the old string a thread takes (derive::Derivation::set_threads);
  // 0: the engine's own (derive::Derivation::kMinChunkBytes).
  std::size_t parallel_chunk_bytes = 0;
  // ran() in rule bodies keyed by the module rather than lpfg's sequence:
  // the same string at any thread count, and such bodies run in parallel.
  bool keyed_random = false;
  // The run's seed (abi::ControlState::seed): replicates of a stochastic
  // model; unset, the model seeds itself as lpfg and cpfg do.
  std::optional<long> seed = {};
};

// The size of images and drawings.
struct OutputOptions {
  int width = 800;  // pixels
  int height = 800;
};

class Simulation {
 public:
  // Printf output and warnings; by default they go to standard error.
  using MessageSink = std::function<void(const std::string&)>;

  // Throws ModelError for anything wrong with the model or its input files.
  // To take an edit of the model or a new -D value, open it again: an
  // unchanged model is not compiled again.
  Simulation(const std::string& model_path, const SimulationOptions& options, MessageSink messages = {});
  Simulation(const std::string& model_path, const build::BuildOptions& options = {}, MessageSink messages = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // ---- the run
  // Start and the axiom; nothing if the run has begun.
  void begin();
  // One derivation step, after begin() if the run has not begun. Returns
  // false, doing nothing, once Stop() was called or the run is finished.
  bool step();
  // End; nothing if the run is finished.
  void finish();
  // A whole run of `steps` steps (the model's derivation length if negative)
  // or until Stop(): begins, steps and finishes. A run in progress goes on
  // from where it is; a finished run is kept if it ended there (or stopped),
  // and run again from the axiom otherwise.
  void run(int steps = -1);
  // Back to before Start: the next begin() starts the run again.
  void rewind();
  // Runs from now on start from `string` instead of the axiom (a saved
  // string, which is not decomposed again). Takes effect at the next begin().
  void start_from(const ModuleString& string);

  // ---- continuous time: differential L-systems (docs/continuous-time.md)
  // Whether the model has derivative or event rules.
  bool continuous() const;
  // How the state is integrated and events located; before the run begins.
  // `settings.end_time` bounds the integrator's steps, so that the steps (and
  // the events) do not depend on the times asked for.
  void set_continuous_settings(const continuous::ContinuousSettings& settings) { continuous_settings_ = settings; }
  // Integrates the state to time `t` (>= time()), firing the events on the
  // way, after begin() if the run has not begun (at t = 0). Throws
  // ModelError where the integration fails or events never settle.
  void advance_to(double t);
  double time() const;
  // Events fired, integrator steps and right-hand side evaluations so far.
  struct ContinuousCounts {
    std::size_t events = 0, steps = 0, evaluations = 0, location_probes = 0;
  };
  ContinuousCounts continuous_counts() const;

  // ---- where the run is
  bool begun() const { return begun_; }
  bool finished() const { return finished_; }
  bool stopped() const;  // Stop() was called in this run
  int step_number() const;  // steps done since the axiom
  int derivation_length() const;
  // Whether productions and decomposition run in parallel, or why not.
  std::string parallel_explanation() const;
  // Seconds each step of this run took, environment and query passes included.
  const std::vector<double>& step_seconds() const { return step_seconds_; }
  // Every distinct warning told so far, in order.
  const std::vector<std::string>& warnings() const;

  // ---- what the string is
  const ModuleString& string() const;
  // As `sylva run --string` writes it.
  std::string string_text() const;
  // The same text written to a file ("-": standard output) as it is made,
  // never whole in memory; the file is replaced only once complete.
  void write_string(const std::string& path) const;
  // The step that made each module of string(), by index (0: the axiom),
  // when track_births(true) was called before the run began; else empty.
  void track_births(bool on);
  const std::vector<std::uint32_t>& birth_steps() const;
  // After view `view`'s interpretation rules (LPFG manual 7.3): what the
  // turtle draws in that view.
  ModuleString interpreted(int view);
  std::string interpreted_text(int view);
  void write_interpreted_string(const std::string& path, int view);
  // The current string drawn by the turtle in view `view` (its vgroup's
  // interpretation rules); without a view, primary_view().
  geometry::Scene scene(int view);
  geometry::Scene scene() { return scene(primary_view()); }
  // The turtle's commands drawing that scene, one per line (sylva run --turtle).
  std::string turtle_trace(int view);

  // ---- outputs
  // The size of images and drawings the model writes itself (OutputFrame)
  // and write() writes.
  void set_output_options(const OutputOptions& options) { output_options_ = options; }
  const OutputOptions& output_options() const { return output_options_; }
  // Writes the current state to each of `paths`, in the format its
  // extension names, once per view the model uses (api/views.h names the
  // files). Each view is drawn once for all the paths.
  void write(const std::vector<std::string>& paths);
  // Whether the model called DisplayFrame since the last time this was asked.
  bool take_display_request();

  // ---- the model and its inputs
  const std::string& model_path() const { return model_path_; }
  const ModuleTypes& types() const;
  const abi::ModelDescriptor& descriptor() const;
  const io::InputFiles& inputs() const { return *inputs_; }
  const turtle::TurtleSettings& turtle_settings() const { return turtle_settings_; }
  bool compiled_now() const { return compiled_now_; }
  // Whether the string's query modules (GetPos ..., cpfg's ?P ...) are
  // filled after the axiom and after every step.
  bool fills_query_modules() const;
  // Views turned on by UseView in this run, in increasing order (empty: the
  // model draws view 0 only), and the first of them.
  const std::vector<int>& views() const { return views_; }
  int primary_view() const { return views_.empty() ? 0 : views_.front(); }
  // The run's limits, and where the run is for their messages.
  const RunBudget& budget() const { return budget_; }

 private:
  void tell(const std::string& text);
  void start_environment(const EnvironmentOptions& options, const std::vector<io::InputFile>& input_files);
  void fill_query_modules();
  // Throws LimitExceeded past the run's time limit or a string's module limit.
  void check_string_limits();
  // Marks what follows as drawing the current string, within the run's limits.
  RunBudget::Scope drawing();
  // Where requests come from: a control statement, or a rule's body (whose
  // LoadString is an error: the string is being rewritten).
  enum class RequestSource { ControlStatement, Rules };
  void act_on_requests(RequestSource source);
  void act_on_request(int request, int value, const std::string& file, RequestSource source);
  void write_requested_frames(bool stopped);

  std::string model_path_;
  // Every message of the run passes here: a warning that repeats is told once,
  // with its count when the simulation ends.
  std::shared_ptr<RepeatedWarnings> warnings_;
  std::unique_ptr<io::InputFiles> inputs_;
  std::unique_ptr<InputAnswers> answers_;
  turtle::TurtleSettings turtle_settings_;
  std::unique_ptr<build::ModelLibrary> library_;
  std::unique_ptr<derive::Derivation> derivation_;
  std::unique_ptr<ModelRequestQueue> requests_;
  // The environment, when the model has one.
  std::shared_ptr<env::Field> field_;
  std::unique_ptr<EnvironmentPass> environment_pass_;
  continuous::ContinuousSettings continuous_settings_;
  class DerivationSystem;  // the derivation as the scheduler sees it (simulation_continuous.cpp)
  std::unique_ptr<DerivationSystem> continuous_system_;
  std::unique_ptr<continuous::ContinuousRun> continuous_run_;
  bool compiled_now_ = false;

  bool begun_ = false;
  bool finished_ = false;
  std::vector<double> step_seconds_;
  RunBudget budget_;
  OutputOptions output_options_;
  std::vector<int> views_;
  std::vector<std::string> pending_frames_;  // OutputFrame: written at the end of the step
  bool display_requested_ = false;
};

}  // namespace sylva
