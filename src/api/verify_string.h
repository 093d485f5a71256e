// VerifyString: (LPFG manual 10.4): a model names the modules its derived
// string must have; a batch run compares module names, not parameters.
#pragma once

#include <string>

#include "api/simulation.h"

namespace sylva {

struct StringVerification {
  enum Outcome { kNoStatement, kSuccess, kFail } outcome = kNoStatement;
  // Module names separated by spaces, as lpfg's Verify_*.txt files hold them.
  std::string expected, actual;
  // On failure: what differs, e.g. "module 3 is 'B', expected 'A'".
  std::string difference;
};

// Compares the simulation's current string with its model's VerifyString:.
StringVerification verify_string(Simulation& simulation);

}  // namespace sylva
