// Which rule bodies may run at the same time as others: a body is safe when
// all it does is compute from its parameters, read the model's variables and
// produce. The analysis works on tokens and is conservative: a body that
// assigns anything but its own locals, declares a static, reads new context,
// calls a function not known to be pure (ran(), Printf, Stop, UseGroup, the
// model's own functions that do such things ...) or does anything it does
// not understand is unsafe, with the reason. Reading global variables is
// safe: the engine runs a pass in parallel only when no body of the pass
// writes them, and control statements run between passes.
#pragma once

#include <string>
#include <vector>

#include "lang/model_ir.h"

namespace sylva::lang {

struct RuleSafety {
  // Empty if the body may run concurrently with other bodies, else why not
  // ("assigns `count`, which is not its own (line 12)").
  std::string reason;
  // The body calls ran(): safe only where ran() draws from a generator keyed
  // by the module rather than from one sequence.
  bool draws_random = false;
};

// For each Rule item of `model`, in item order.
std::vector<RuleSafety> rule_safety(const Model& model);

}  // namespace sylva::lang
