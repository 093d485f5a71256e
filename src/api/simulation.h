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
#include "geometry/scene.h"
#include "io/input_files.h"
#include "turtle/turtle_settings.h"

namespace sylva {

class InputAnswers;

struct SimulationOptions {
  build::BuildOptions build;
  // View, animation, colormap, material, contour and function files, in the
  // order given (lpfg's command line): ids of contours and functions follow it.
  std::vector<std::string> input_files;
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

 private:
  std::unique_ptr<io::InputFiles> inputs_;
  std::unique_ptr<InputAnswers> answers_;
  turtle::TurtleSettings turtle_settings_;
  std::unique_ptr<build::ModelLibrary> library_;
  std::unique_ptr<derive::Derivation> derivation_;
  bool compiled_now_ = false;
};

}  // namespace sylva
