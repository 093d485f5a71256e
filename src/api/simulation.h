// The public entry point of the engine: a model file, built (or taken from the
// cache), loaded, and ready to derive. Front doors (the command line, the
// studio, tests) go through here.
#pragma once

#include <memory>
#include <string>

#include "build/model_builder.h"
#include "build/model_library.h"
#include "derive/derivation.h"

namespace sylva {

class Simulation {
 public:
  // Throws ModelError for anything wrong with the model.
  Simulation(const std::string& model_path, const build::BuildOptions& options = {},
             derive::Derivation::MessageSink messages = {});

  derive::Derivation& derivation() { return *derivation_; }
  const ModuleTypes& types() const { return derivation_->types(); }
  bool compiled_now() const { return compiled_now_; }

 private:
  std::unique_ptr<build::ModelLibrary> library_;
  std::unique_ptr<derive::Derivation> derivation_;
  bool compiled_now_ = false;
};

}  // namespace sylva
