// Reads an experiment plan from TOML (toml++), checking each key where it is
// written: the errors name the plan's line and column.
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "experiment/plan.h"
#include "experiment/sample_stream.h"
#include "experiment/toml_text.h"

namespace sylva::experiment {
namespace {

namespace fs = std::filesystem;

class Reader {
 public:
  Reader(std::string path) : path_(std::move(path)), base_(fs::absolute(fs::path(path_)).parent_path()) {}

  SourceLocation at(const toml::node& node) const { return at(node.source()); }
  SourceLocation at(const toml::source_region& region) const {
    return {path_, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
  }
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const { throw ModelError(at(node), message); }

  std::string absolute(const std::string& relative) const {
    return fs::weakly_canonical(base_ / fs::path(relative)).string();
  }

  const std::string& string(const toml::node& node, const std::string& key) const {
    if (!node.is_string()) fail(node, "'" + key + "' must be a string");
    return node.as_string()->get();
  }
  double number(const toml::node& node, const std::string& key) const {
    if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
    if (node.is_floating_point()) return node.as_floating_point()->get();
    fail(node, "'" + key + "' must be a number");
  }
  long integer(const toml::node& node, const std::string& key, long least) const {
    if (!node.is_integer()) fail(node, "'" + key + "' must be a whole number");
    const long value = static_cast<long>(node.as_integer()->get());
    if (value < least) fail(node, "'" + key + "' must be at least " + std::to_string(least));
    return value;
  }
  const toml::array& array(const toml::node& node, const std::string& key) const {
    if (!node.is_array()) fail(node, "'" + key + "' must be a list [ ... ]");
    return *node.as_array();
  }
  const toml::table& table(const toml::node& node, const std::string& key) const {
    if (!node.is_table()) fail(node, "'" + key + "' must be a table");
    return *node.as_table();
  }
  // The keys of a table in the order they are written (toml++ keeps them sorted).
  static std::vector<std::pair<std::string, const toml::node*>> in_order(const toml::table& t) {
    std::vector<std::pair<std::string, const toml::node*>> out;
    for (const auto& [key, node] : t) out.emplace_back(std::string(key.str()), &node);
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
      const auto& x = a.second->source().begin;
      const auto& y = b.second->source().begin;
      return x.line != y.line ? x.line < y.line : x.column < y.column;
    });
    return out;
  }
  void only_keys(const toml::table& t, std::initializer_list<const char*> known, const std::string& where) const {
    for (const auto& [key, node] : t) {
      const std::string name(key.str());
      if (std::none_of(known.begin(), known.end(), [&](const char* k) { return name == k; })) {
        std::string list;
        for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        throw ModelError(at(key.source()), "unknown key '" + name + "'" + where + " (expected one of: " + list + ")");
      }
    }
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  fs::path base_;
};

// The most values a parameter takes, and the most runs a plan makes.
constexpr long kMostValues = 1000000;
constexpr double kMostRuns = 1e7;

// A number as -D should get it: integers as integers, others with up to 12
// significant digits so that 0.1 + 2 · 0.1 is written 0.3.
std::string number_text(double value) {
  if (std::nearbyint(value) == value && std::fabs(value) < 1e15) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.0f", value);
    return buffer;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", value);
  return buffer;
}

std::string value_text(const Reader& r, const toml::node& node, const std::string& name) {
  if (node.is_integer()) return std::to_string(node.as_integer()->get());
  if (node.is_floating_point()) return number_text(node.as_floating_point()->get());
  if (node.is_boolean()) return node.as_boolean()->get() ? "1" : "0";
  if (node.is_string()) return node.as_string()->get();
  r.fail(node, "the values of '" + name + "' must be numbers or strings");
}

std::vector<std::string> parameter_values(const Reader& r, const toml::node& node, const std::string& name, long seed) {
  std::vector<std::string> values;
  if (node.is_array()) {
    for (const toml::node& value : *node.as_array()) values.push_back(value_text(r, value, name));
    if (values.empty()) r.fail(node, "'" + name + "' has no values");
    return values;
  }
  if (!node.is_table()) {
    values.push_back(value_text(r, node, name));
    return values;
  }
  const toml::table& spec = *node.as_table();
  r.only_keys(spec, {"from", "to", "step", "count", "uniform", "samples"}, " in the values of '" + name + "'");
  if (spec.contains("uniform")) {
    const toml::array& bounds = r.array(*spec.get("uniform"), "uniform");
    if (bounds.size() != 2) r.fail(*spec.get("uniform"), "'uniform' takes two numbers: [low, high]");
    const double low = r.number(*bounds.get(0), "uniform"), high = r.number(*bounds.get(1), "uniform");
    if (!(low < high)) r.fail(*spec.get("uniform"), "'uniform' needs low < high");
    if (!spec.contains("samples")) r.fail(node, "'uniform' needs 'samples = N'");
    const long count = r.integer(*spec.get("samples"), "samples", 1);
    if (count > kMostValues) r.fail(*spec.get("samples"), "at most 10^6 samples");
    // The draws depend on the plan's seed and the parameter's name only.
    SampleStream stream(seed, name);
    for (long i = 0; i < count; ++i) values.push_back(number_text(low + (high - low) * stream.next()));
    return values;
  }
  if (!spec.contains("from") || !spec.contains("to"))
    r.fail(node, "a range of '" + name + "' needs 'from' and 'to' (and 'step' or 'count'), or 'uniform' and 'samples'");
  const double from = r.number(*spec.get("from"), "from"), to = r.number(*spec.get("to"), "to");
  if (spec.contains("count")) {
    const long count = r.integer(*spec.get("count"), "count", 1);
    if (count > kMostValues) r.fail(*spec.get("count"), "at most 10^6 values");
    if (count == 1 && from != to) r.fail(*spec.get("count"), "'count = 1' needs from = to");
    for (long i = 0; i < count; ++i) values.push_back(number_text(count == 1 ? from : from + (to - from) * i / (count - 1)));
    return values;
  }
  if (!spec.contains("step")) r.fail(node, "a range of '" + name + "' needs 'step' or 'count'");
  const double step = r.number(*spec.get("step"), "step");
  if (step == 0 || !std::isfinite(step)) r.fail(*spec.get("step"), "'step' must not be 0");
  const double span = (to - from) / step;
  if (span < -1e-9) r.fail(node, "the range of '" + name + "' has no values: from " + number_text(from) + " never reaches " +
                                     number_text(to) + " by " + number_text(step));
  const long count = static_cast<long>(std::floor(span + 1e-9)) + 1;
  if (count > kMostValues)
    r.fail(node, "the range of '" + name + "' has " + std::to_string(count) + " values (at most 10^6)");
  for (long i = 0; i < count; ++i) values.push_back(number_text(from + step * i));
  return values;
}

void read_save(const Reader& r, const toml::table& t, Plan& plan, const toml::node& node) {
  r.only_keys(t, {"runs", "formats", "directory"}, " in [save]");
  SavePlan save;
  if (const toml::node* runs = t.get("runs")) {
    if (runs->is_string() && runs->as_string()->get() == "all") {
      save.all_runs = true;
    } else {
      for (const toml::node& n : r.array(*runs, "runs")) save.runs.push_back(r.integer(n, "runs", 0));
    }
  } else {
    save.all_runs = true;
  }
  if (const toml::node* formats = t.get("formats")) {
    for (const toml::node& n : r.array(*formats, "formats")) save.formats.push_back(r.string(n, "formats"));
  }
  if (save.formats.empty()) r.fail(node, "[save] needs 'formats' (e.g. [\"str\", \"png\"])");
  const toml::node* directory = t.get("directory");
  save.directory = r.absolute(directory ? r.string(*directory, "directory") : "runs");
  plan.save = std::move(save);
}

void read_plot(const Reader& r, const toml::table& t, Plan& plan, const toml::node& node) {
  r.only_keys(t, {"x", "y", "file"}, " in [plot]");
  PlotPlan plot;
  for (const char* key : {"x", "y", "file"})
    if (!t.contains(key)) r.fail(node, std::string("[plot] needs '") + key + "'");
  plot.x = r.string(*t.get("x"), "x");
  plot.y = r.string(*t.get("y"), "y");
  plot.file = r.absolute(r.string(*t.get("file"), "file"));
  if (std::none_of(plan.parameters.begin(), plan.parameters.end(), [&](const Parameter& p) { return p.name == plot.x; }))
    r.fail(*t.get("x"), "[plot] x '" + plot.x + "' is not a parameter of the plan");
  if (std::none_of(plan.measures.begin(), plan.measures.end(), [&](const MeasureSpec& m) { return m.name == plot.y; }))
    r.fail(*t.get("y"), "[plot] y '" + plot.y + "' is not a measure of the plan");
  plan.plot = std::move(plot);
}

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

Plan read(const toml::table& root, const Reader& r) {
  r.only_keys(root,
              {"model", "inputs", "parameters", "design", "replicates", "seed", "steps", "times", "measures", "output",
               "timeout", "save", "plot"},
              "");
  Plan plan;
  plan.path = r.path();
  const toml::node* model = root.get("model");
  if (!model) throw ModelError(SourceLocation{r.path(), 1, 1}, "the plan needs 'model = \"FILE\"'");
  plan.model = r.absolute(r.string(*model, "model"));
  plan.model_at = r.at(*model);
  if (!fs::exists(plan.model)) r.fail(*model, "no model file " + plan.model);
  if (const toml::node* inputs = root.get("inputs")) {
    for (const toml::node& n : r.array(*inputs, "inputs")) {
      plan.inputs.push_back(r.absolute(r.string(n, "inputs")));
      if (!fs::exists(plan.inputs.back())) r.fail(n, "no input file " + plan.inputs.back());
    }
  }
  if (const toml::node* seed = root.get("seed")) plan.seed = r.integer(*seed, "seed", 0);
  if (const toml::node* replicates = root.get("replicates")) {
    const long count = r.integer(*replicates, "replicates", 1);
    if (count > kMostRuns) r.fail(*replicates, "at most 10^7 replicates");
    plan.replicates = static_cast<int>(count);
  }
  if (const toml::node* design = root.get("design")) {
    const std::string& d = r.string(*design, "design");
    if (d != "grid" && d != "zip") r.fail(*design, "'design' is \"grid\" (every combination) or \"zip\" (the i-th values together)");
    plan.zip = d == "zip";
  }
  if (const toml::node* parameters = root.get("parameters")) {
    for (const auto& [name, node] : Reader::in_order(r.table(*parameters, "parameters"))) {
      if (!is_identifier(name)) r.fail(*node, "'" + name + "' is not a name -D can define");
      plan.parameters.push_back({name, parameter_values(r, *node, name, plan.seed), r.at(*node)});
    }
  }
  if (plan.zip) {
    for (const Parameter& p : plan.parameters)
      if (p.values.size() != plan.parameters.front().values.size())
        throw ModelError(p.at, "with design = \"zip\" every parameter needs as many values as '" +
                                   plan.parameters.front().name + "' (" + std::to_string(plan.parameters.front().values.size()) +
                                   "); '" + p.name + "' has " + std::to_string(p.values.size()));
  }
  double runs = std::max(plan.replicates, 1);
  if (plan.zip && !plan.parameters.empty()) runs *= static_cast<double>(plan.parameters.front().values.size());
  for (const Parameter& p : plan.parameters)
    if (!plan.zip) runs *= static_cast<double>(p.values.size());
  if (runs > kMostRuns)
    throw ModelError(plan.parameters.empty() ? r.at(*root.get("replicates")) : plan.parameters.front().at,
                     "the plan makes " + number_text(runs) + " runs (at most 10^7)");
  if (root.contains("steps") && root.contains("times"))
    r.fail(*root.get("times"), "give 'steps' (derivation steps) or 'times' (a continuous model), not both");
  if (const toml::node* steps = root.get("steps")) {
    for (const toml::node& n : r.array(*steps, "steps")) plan.steps.push_back(static_cast<int>(r.integer(n, "steps", 0)));
    if (plan.steps.empty()) r.fail(*steps, "'steps' has no values");
  }
  if (const toml::node* times = root.get("times")) {
    for (const toml::node& n : r.array(*times, "times")) {
      plan.times.push_back(r.number(n, "times"));
      if (plan.times.back() < 0) r.fail(n, "times are at least 0");
    }
    if (plan.times.empty()) r.fail(*times, "'times' has no values");
  }
  std::sort(plan.steps.begin(), plan.steps.end());
  plan.steps.erase(std::unique(plan.steps.begin(), plan.steps.end()), plan.steps.end());
  std::sort(plan.times.begin(), plan.times.end());
  plan.times.erase(std::unique(plan.times.begin(), plan.times.end()), plan.times.end());
  if (const toml::node* measures = root.get("measures")) {
    std::set<std::string> columns = {"run", "point", "replicate", "seed", "step", "time", "status", "error"};
    for (const Parameter& p : plan.parameters) columns.insert(p.name);
    for (const auto& [name, node] : Reader::in_order(r.table(*measures, "measures"))) {
      if (columns.count(name)) r.fail(*node, "the measure '" + name + "' would repeat a column of the table");
      SourceLocation where = r.at(*node);
      ++where.column;  // past the opening quote
      plan.measures.push_back({name, r.string(*node, name), where});
    }
  }
  if (plan.measures.empty())
    throw ModelError(SourceLocation{r.path(), 1, 1}, "the plan measures nothing: add a [measures] table, e.g. "
                                                     "apices = \"count(A)\"");
  const toml::node* output = root.get("output");
  plan.output = output ? r.absolute(r.string(*output, "output"))
                       : (fs::path(r.absolute(fs::path(r.path()).filename().string())).replace_extension(".csv")).string();
  if (const toml::node* timeout = root.get("timeout")) {
    plan.timeout_seconds = r.number(*timeout, "timeout");
    if (plan.timeout_seconds <= 0) r.fail(*timeout, "'timeout' is a number of seconds above 0");
  }
  if (const toml::node* save = root.get("save")) read_save(r, r.table(*save, "save"), plan, *save);
  if (const toml::node* plot = root.get("plot")) read_plot(r, r.table(*plot, "plot"), plan, *plot);
  return plan;
}

}  // namespace

Plan parse_plan(const std::string& text, const std::string& path) {
  const Reader reader(path);
  toml::table root;
  try {
    root = toml::parse(toml_text_for_parser(text, path), path);
  } catch (const toml::parse_error& error) {
    throw ModelError(reader.at(error.source()), std::string(error.description()));
  }
  return read(root, reader);
}

Plan read_plan(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError("cannot read the plan " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_plan(text.str(), path);
}

}  // namespace sylva::experiment
