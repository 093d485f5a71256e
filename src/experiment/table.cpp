#include "experiment/table.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace sylva::experiment {
namespace {

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string number_cell(double value) {
  if (std::isnan(value)) return "NA";
  if (std::isinf(value)) return value > 0 ? "Inf" : "-Inf";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string table_text(const Plan& plan, const std::vector<RunSpec>& runs, const std::vector<RunResult>& results) {
  const bool timed = !plan.times.empty();
  std::string out = "run,point,replicate,seed";
  for (const Parameter& p : plan.parameters) out += "," + quoted(p.name);
  out += timed ? ",time" : ",step";
  for (const MeasureSpec& m : plan.measures) out += "," + quoted(m.name);
  out += ",status,error\n";
  const std::size_t planned = timed ? plan.times.size() : std::max<std::size_t>(plan.steps.size(), 1);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunSpec& run = runs[i];
    const RunResult& result = results[i];
    std::string head = std::to_string(run.number) + "," + std::to_string(run.point) + "," + std::to_string(run.replicate) +
                       "," + (run.seed ? std::to_string(*run.seed) : "NA");
    for (const auto& [name, value] : run.values) head += "," + quoted(value);
    for (std::size_t k = 0; k < planned; ++k) {
      out += head;
      const RunRow* row = k < result.rows.size() ? &result.rows[k] : nullptr;
      if (timed) out += "," + number_cell(plan.times[k]);
      else out += "," + (plan.steps.empty() ? (row ? std::to_string(row->step) : std::string("NA"))
                                            : std::to_string(plan.steps[k]));
      for (std::size_t m = 0; m < plan.measures.size(); ++m)
        out += "," + (row && m < row->values.size() ? number_cell(row->values[m]) : std::string("NA"));
      if (row && row->note.empty()) out += ",ok,\n";
      else if (row) out += ",ended," + quoted(row->note) + "\n";
      else out += ",error," + quoted(result.error.empty() ? "no result" : result.error) + "\n";
    }
  }
  return out;
}

}  // namespace sylva::experiment
