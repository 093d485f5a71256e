// Helpers for the tests of examples/: reading the text form of a string back
// into modules, the branching-structure walks the labelling examples are
// checked against, and running a model step by step.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test::examples {

// One module of a string in the text form: `Name` or `Name(p1,p2,...)`.
struct Module {
  std::string name;
  std::vector<std::string> params;  // as printed; a struct is one parameter "{a=1,b=2}"
};

// Splits `text` at commas that are not inside (), {} or [].
inline std::vector<std::string> split_top_level(const std::string& text) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  for (char c : text) {
    if (c == '(' || c == '{' || c == '[') ++depth;
    if (c == ')' || c == '}' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      parts.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) parts.push_back(current);
  return parts;
}

// Modules are separated by single spaces and contain no spaces themselves.
inline std::vector<Module> parse_modules(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::vector<Module> modules;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find(' ', pos);
    if (end == std::string::npos) end = text.size();
    std::string token = text.substr(pos, end - pos);
    pos = end + 1;
    if (token.empty()) continue;
    Module m;
    std::size_t open = token.find('(');
    m.name = token.substr(0, open);
    if (open != std::string::npos) m.params = split_top_level(token.substr(open + 1, token.size() - open - 2));
    modules.push_back(m);
  }
  return modules;
}

inline std::vector<std::string> names(const std::vector<Module>& modules) {
  std::vector<std::string> out;
  for (const Module& m : modules) out.push_back(m.name);
  return out;
}

inline int count_named(const std::vector<Module>& modules, const std::string& name) {
  int n = 0;
  for (const Module& m : modules) n += m.name == name;
  return n;
}

inline double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }
// A float parameter printed with %.9g reads back to the same float.
inline float float_number(const std::string& text) { return std::strtof(text.c_str(), nullptr); }

// The value of `field` in a struct parameter printed as {a=1,b=2,...}.
inline std::string field(const std::string& text, const std::string& name) {
  for (const std::string& part : split_top_level(text.substr(1, text.size() - 2))) {
    std::size_t eq = part.find('=');
    if (part.substr(0, eq) == name) return part.substr(eq + 1);
  }
  ADD_FAILURE() << "no field " << name << " in " << text;
  return "";
}

// The first parameter of every I, in string order.
inline std::vector<int> labels_of_I(const std::vector<Module>& modules, std::size_t param = 0) {
  std::vector<int> out;
  for (const Module& m : modules)
    if (m.name == "I") out.push_back(static_cast<int>(number(m.params.at(param))));
  return out;
}

// Index just past the EB that closes the branch `from` is in (or the end).
inline std::size_t end_of_branch(const std::vector<Module>& s, std::size_t from) {
  int level = 0;
  for (std::size_t j = from; j < s.size(); ++j) {
    if (s[j].name == "SB") ++level;
    if (s[j].name == "EB" && level-- == 0) return j;
  }
  return s.size();
}

// Developmental (centrifugal) label of every I, in string order: the number of
// I's on the path from the root to it, itself included (root = 1). A walk
// with a stack of path lengths, one entry per open branch.
inline std::vector<int> depths_of_I(const std::vector<Module>& s) {
  std::vector<int> out, saved;
  int depth = 0;
  for (const Module& m : s) {
    if (m.name == "SB") saved.push_back(depth);
    if (m.name == "EB") depth = saved.back(), saved.pop_back();
    if (m.name == "I") out.push_back(++depth);
  }
  return out;
}

// Functional (centripetal) label of every I, in string order: the number of
// apices A it supports, i.e. the A's after it up to the end of its branch.
inline std::vector<int> apices_above_I(const std::vector<Module>& s) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].name != "I") continue;
    int apices = 0;
    for (std::size_t j = i + 1; j < end_of_branch(s, i + 1); ++j) apices += s[j].name == "A";
    out.push_back(apices);
  }
  return out;
}

// A model loaded once and derived step by step.
class Stepper {
 public:
  explicit Stepper(const std::string& model, std::vector<std::string> defines = {}) {
    build::BuildOptions options;
    options.cache_dir = SYLVA_TEST_CACHE_DIR;
    options.defines = std::move(defines);
    simulation_ = std::make_unique<Simulation>(model, options, [this](const std::string& m) { messages += m; });
    simulation_->begin();
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) simulation_->step();
  }
  int steps_done() { return simulation_->step_number(); }
  std::string text() { return trim(io::format_string(simulation_->string(), simulation_->types())); }
  std::vector<Module> modules() { return parse_modules(text()); }
  std::string interpreted() {
    return trim(io::format_string(simulation_->interpreted(0), simulation_->types()));
  }

  std::string messages;

 private:
  static std::string trim(std::string s) {
    if (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
  }
  std::unique_ptr<Simulation> simulation_;
};

// The string of `model` after `steps` steps, built with preprocessor `defines`.
inline std::string derive_with(const std::string& model, int steps, std::vector<std::string> defines) {
  Stepper run(model, std::move(defines));
  run.step(steps);
  return run.text();
}

}  // namespace sylva::test::examples
