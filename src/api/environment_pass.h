// The environmental pass of open L-systems (EnviroManual 1.4): the string
// interpreted by the turtle, a Query at every communication module (lpfg's
// E1, E2 and EA20, cpfg's ?E), one call to the Field with all of them, and
// the answers written into the modules' parameters.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "derive/derivation.h"
#include "env/comm_spec.h"
#include "env/field.h"
#include "support/diagnostic.h"
#include "turtle/turtle_settings.h"

namespace sylva {

class EnvironmentPass {
 public:
  // `clean_ea20` (lpfg's -cleanEA20): an EA20's twenty values are zeroed
  // before the answers are written, so values the program does not send are
  // 0 rather than what the module held. `verbose` receives a line per pass
  // when the .e file says "verbose: on". Throws ModelError naming
  // `model_file` if a cpfg ?E has more than 20 parameters.
  EnvironmentPass(env::CommSpec spec, const ModuleTypes& types, bool clean_ea20, const std::string& model_file,
                  std::function<void(const std::string&)> verbose = {});

  // One pass over the derivation's current string, answered by `field`.
  // Throws ModelError if the field answers a parameter a module lacks.
  void run(derive::Derivation& derivation, const turtle::TurtleSettings& settings, env::Field& field);

  // Parameters of a communication module of type `id` (1, 2, 20, or a ?E's
  // count); -1 for other modules.
  int parameter_count(ModuleId id) const { return id < counts_.size() ? counts_[id] : -1; }

 private:
  void check_answer(const env::Query& query, const env::Answer& answer, int step) const;
  std::string answerer() const;
  SourceLocation answerer_location() const;

  env::CommSpec spec_;
  bool clean_ea20_;
  std::string model_file_;  // names the model in errors without a .e file
  std::function<void(const std::string&)> verbose_;
  std::vector<int> counts_;  // by module id
  ModuleId ea20_ = abi::kNoModule;
};

}  // namespace sylva
