// The public entry point of the engine: a model file and its input files,
// built (or taken from the cache), loaded, and ready to derive and to turn
// into geometry. Front doors (the command line, the studio, tests) go
// through here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "build/model_builder.h"
#include "build/model_library.h"
#include "derive/derivation.h"
#include "env/field.h"
#include "geometry/scene.h"
#include "inputs/input_files.h"
#include "turtle/turtle_settings.h"

namespace sylva {

class InputAnswers;
class RepeatedWarnings;
class EnvironmentPass;
class ModelRequests;
struct OutputOptions;

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
};

class Simulation {
 public:
  // Throws ModelError for anything wrong with the model or its input files.
  Simulation(const std::string& model_path, const SimulationOptions& options,
             derive::Derivation::MessageSink messages = {});
  Simulation(const std::string& model_path, const build::BuildOptions& options = {},
             derive::Derivation::MessageSink messages = {});
  ~Simulation();

  derive::Derivation& derivation() { return *derivation_; }
  const ModuleTypes& types() const { return derivation_->types(); }
  const io::InputFiles& inputs() const { return *inputs_; }
  const turtle::TurtleSettings& turtle_settings() const { return turtle_settings_; }
  bool compiled_now() const { return compiled_now_; }

  // The current string drawn by the turtle; `trace` receives the turtle's
  // commands one per line.
  geometry::Scene scene(std::string* trace = nullptr);
  // The same drawn in view `view` (its vgroup's interpretation rules, LPFG
  // manual 7.3); scene() draws primary_view().
  geometry::Scene scene(int view, std::string* trace = nullptr);

  const std::string& model_path() const { return model_path_; }
  const abi::ModelDescriptor& descriptor() const { return library_->descriptor(); }
  // Views turned on by UseView in this run, in increasing order (empty: the
  // model draws view 0 only), and the first of them.
  const std::vector<int>& views() const;
  int primary_view() const { return views().empty() ? 0 : views().front(); }
  // The size of images the model writes itself (OutputFrame).
  void set_output_options(const OutputOptions& options);
  // Whether the model called DisplayFrame since the last time this was asked.
  bool take_display_request();

 private:
  // Every message of the run passes here: a warning that repeats is told once,
  // with its count when the simulation ends.
  std::shared_ptr<RepeatedWarnings> warnings_;
  std::unique_ptr<io::InputFiles> inputs_;
  std::unique_ptr<InputAnswers> answers_;
  turtle::TurtleSettings turtle_settings_;
  std::unique_ptr<build::ModelLibrary> library_;
  std::unique_ptr<derive::Derivation> derivation_;
  // The environment, when the model has one (kept before the pass that uses it).
  std::shared_ptr<env::Field> field_;
  std::unique_ptr<EnvironmentPass> environment_pass_;
  void start_environment(const EnvironmentOptions& options, const std::vector<io::InputFile>& input_files,
                         const derive::Derivation::MessageSink& messages);
  std::unique_ptr<ModelRequests> requests_;
  std::string model_path_;
  bool compiled_now_ = false;
};

}  // namespace sylva
