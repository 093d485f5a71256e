#include "api/verify_string.h"

#include <vector>

namespace sylva {

StringVerification verify_string(Simulation& simulation) {
  StringVerification result;
  const abi::ModelDescriptor& model = simulation.descriptor();
  if (model.verify_length < 0) return result;

  const ModuleTypes& types = simulation.types();
  const std::vector<ModuleId> expected(model.verify_string, model.verify_string + model.verify_length);
  std::vector<ModuleId> actual;
  const ModuleString& string = simulation.string();
  const StringView v = string.view(types);
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) actual.push_back(v.id_at(at));

  auto names = [&](const std::vector<ModuleId>& ids) {
    std::string text;
    for (std::size_t k = 0; k < ids.size(); ++k) text += (k ? " " : "") + types.name(ids[k]);
    return text + "\n";
  };
  result.expected = names(expected);
  result.actual = names(actual);
  if (expected == actual) {
    result.outcome = StringVerification::kSuccess;
    return result;
  }
  result.outcome = StringVerification::kFail;
  std::size_t k = 0;
  while (k < expected.size() && k < actual.size() && expected[k] == actual[k]) ++k;
  const std::string position = "module " + std::to_string(k + 1);
  if (k == actual.size())
    result.difference = "the string ends after " + std::to_string(actual.size()) + " modules; expected " +
                        std::to_string(expected.size()) + ", " + position + " being '" + types.name(expected[k]) + "'";
  else if (k == expected.size())
    result.difference = "the string has " + std::to_string(actual.size()) + " modules; expected " +
                        std::to_string(expected.size()) + " (" + position + " is '" + types.name(actual[k]) + "')";
  else
    result.difference = position + " is '" + types.name(actual[k]) + "', expected '" + types.name(expected[k]) + "'";
  return result;
}

}  // namespace sylva
