// What UseGroup(N) (LPFG manual 4.4) selects, as lpfg takes it. lpfg numbers
// its groups 0 to the largest declared (`group N:` or `ggroup N:`):
//   - a number outside that range is ignored, the group stays as it was;
//   - a number inside it that no group declares is selected, and the steps
//     made with it apply no productions (lpfg says the group's kind is not
//     handled and goes on).
// Neither stops lpfg, so neither stops a run: each is a warning, once per
// group number, at the UseGroup call.
#pragma once

#include <string>

#include "sylva/abi.h"

namespace sylva::derive {

enum class GroupChoice { Defined, OutOfRange, Undeclared };

GroupChoice classify_group(const abi::ModelDescriptor& model, int group);

// "file:line: warning: ..." for a group that is not Defined, at the
// UseGroup call (file and line, as the model recorded them).
std::string group_warning(const abi::ModelDescriptor& model, int group, GroupChoice choice);

}  // namespace sylva::derive
