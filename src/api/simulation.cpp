#include "api/simulation.h"

namespace sylva {

Simulation::Simulation(const std::string& model_path, const build::BuildOptions& options,
                       derive::Derivation::MessageSink messages) {
  build::BuiltModel built = build::build_model(model_path, options);
  compiled_now_ = built.compiled_now;
  library_ = std::make_unique<build::ModelLibrary>(built.library_path);
  derivation_ = std::make_unique<derive::Derivation>(library_->descriptor(), std::move(messages));
}

}  // namespace sylva
