// UseGroup(N) (LPFG manual 4.4) may select only a group the model defines:
// group 0, or one named by `group N:` or `ggroup N:`. A step with any other
// group would silently apply group 0's rules only; it is an error instead.
#pragma once

#include "sylva/abi.h"

namespace sylva::derive {

// Throws ModelError at the UseGroup call (file and line, as the model
// recorded them) when `group` is not one of the model's groups.
void require_defined_group(const abi::ModelDescriptor& model, int group);

}  // namespace sylva::derive
