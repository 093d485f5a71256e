#include "experiment/runs.h"

#include "experiment/sample_stream.h"

#include <algorithm>
#include <set>

namespace sylva::experiment {

std::vector<std::string> RunSpec::defines() const {
  std::vector<std::string> out;
  for (const auto& [name, value] : values) out.push_back(name + "=" + value);
  return out;
}

std::vector<RunSpec> plan_runs(const Plan& plan) {
  // The points: one value per parameter.
  std::vector<std::vector<std::size_t>> points;
  if (plan.parameters.empty()) {
    points.emplace_back();
  } else if (plan.zip) {
    for (std::size_t i = 0; i < plan.parameters.front().values.size(); ++i)
      points.emplace_back(plan.parameters.size(), i);
  } else {
    std::vector<std::size_t> at(plan.parameters.size(), 0);
    for (;;) {
      points.push_back(at);
      std::size_t k = at.size();
      while (k > 0 && ++at[k - 1] == plan.parameters[k - 1].values.size()) at[--k] = 0;
      if (k == 0) break;
    }
  }
  const int replicates = std::max(plan.replicates, 1);
  std::vector<RunSpec> runs;
  runs.reserve(points.size() * replicates);
  for (std::size_t p = 0; p < points.size(); ++p) {
    for (int r = 0; r < replicates; ++r) {
      RunSpec run;
      run.number = static_cast<long>(runs.size());
      run.point = static_cast<long>(p);
      run.replicate = r;
      if (plan.replicates > 0) run.seed = replicate_seed(plan.seed, r);
      for (std::size_t k = 0; k < plan.parameters.size(); ++k)
        run.values.emplace_back(plan.parameters[k].name, plan.parameters[k].values[points[p][k]]);
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::vector<RunSpec> one_run_per_define_set(const std::vector<RunSpec>& runs) {
  std::vector<RunSpec> out;
  std::set<std::vector<std::string>> seen;
  for (const RunSpec& run : runs)
    if (seen.insert(run.defines()).second) out.push_back(run);
  return out;
}

}  // namespace sylva::experiment
