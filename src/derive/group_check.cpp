#include "derive/group_check.h"

#include <algorithm>
#include <string>

#include "support/diagnostic.h"

namespace sylva::derive {
namespace {

bool defines_group(const abi::ModelDescriptor& model, int group) {
  if (group == 0) return true;
  auto in = [group](const int* list, std::uint32_t count) {
    return list && std::find(list, list + count, group) != list + count;
  };
  if (in(model.groups, model.group_count) || in(model.gillespie_groups, model.gillespie_group_count)) return true;
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
