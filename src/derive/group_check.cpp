#include "derive/group_check.h"

#include <algorithm>

#include "derive/gillespie.h"

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

// The largest group number the model declares (lpfg's number of groups - 1).
int last_group(const abi::ModelDescriptor& model) {
  int last = 0;
  for (std::uint32_t k = 0; model.groups && k < model.group_count; ++k) last = std::max(last, model.groups[k]);
  for (std::uint32_t k = 0; model.gillespie_groups && k < model.gillespie_group_count; ++k)
    last = std::max(last, model.gillespie_groups[k]);
  for (std::uint32_t r = 0; r < model.rule_count; ++r) last = std::max(last, model.rules[r].group);
  return last;
}

}  // namespace

GroupChoice classify_group(const abi::ModelDescriptor& model, int group) {
  // cpfg's sub-L-systems number their rules by L-system, not by group.
  if (model.flags & abi::kModelSubLsystems) return GroupChoice::Defined;
  if (defines_group(model, group)) return GroupChoice::Defined;
  if (group < 0 || group > last_group(model)) return GroupChoice::OutOfRange;
  return GroupChoice::Undeclared;
}

std::string group_warning(const abi::ModelDescriptor& model, int group, GroupChoice choice) {
  const abi::ControlState& c = *model.control;
  const bool located = c.group_call_file && c.group_call_line > 0;
  std::string where = located ? std::string(c.group_call_file) + ":" + std::to_string(c.group_call_line)
                              : std::string(model.source_file ? model.source_file : "model");
  const std::string n = std::to_string(group);
  if (choice == GroupChoice::OutOfRange)
    return where + ": warning: UseGroup(" + n + ") selects no group: the model's groups are 0 to " +
           std::to_string(last_group(model)) + "; ignored, as lpfg ignores it\n";
  return where + ": warning: UseGroup(" + n + ") selects group " + n + ", which the model does not declare ('group " +
         n + ":'); its steps apply no productions, as in lpfg\n";
}

}  // namespace sylva::derive
