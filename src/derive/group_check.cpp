#include "derive/group_check.h"

#include <algorithm>
#include <string>

#include "derive/gillespie.h"
#include "support/diagnostic.h"

namespace sylva::derive {
namespace {

bool defines_group(const abi::ModelDescriptor& model, int group) {
  if (group == 0) return true;
  const int* groups = model.groups;
  if (groups && std::find(groups, groups + model.group_count, group) != groups + model.group_count) return true;
  if (is_gillespie_group(model, group)) return true;
  // A rule in the group defines it too (models whose groups come from elsewhere).
  for (std::uint32_t r = 0; r < model.rule_count; ++r)
    if (model.rules[r].group == group) return true;
  return false;
}

}  // namespace

void require_defined_group(const abi::ModelDescriptor& model, int group) {
  // cpfg's sub-L-systems number their rules by L-system, not by group.
  if (model.flags & abi::kModelSubLsystems) return;
  if (defines_group(model, group)) return;
  const abi::ControlState& c = *model.control;
  const bool located = c.group_call_file && c.group_call_line > 0;
  throw ModelError(SourceLocation{located ? c.group_call_file : model.source_file, located ? c.group_call_line : 0, 0},
                   "UseGroup(" + std::to_string(group) + ") selects group " + std::to_string(group) +
                       ", but the model defines no 'group " + std::to_string(group) + ":'");
}

}  // namespace sylva::derive
