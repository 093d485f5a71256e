// Helpers for the tests of the course notes' numerical models in examples/
// ("L-systems and Beyond", SIGGRAPH 2003). Every expected value in those
// tests is worked out there: in closed form, by a linear stability analysis,
// by Eigen's dense solvers, or by a plain C++ loop; none is copied from the
// program's output.
#pragma once

#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples::notes {

inline std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

// The parameters of every module named `name`, as numbers.
inline std::vector<std::vector<double>> params_of(const std::vector<Module>& s, const std::string& name) {
  std::vector<std::vector<double>> out;
  for (const Module& m : s) {
    if (m.name != name) continue;
    std::vector<double> p;
    for (const std::string& text : m.params) p.push_back(number(text));
    out.push_back(p);
  }
  return out;
}

inline double field_of(const std::string& text, const std::string& name) { return number(field(text, name)); }

}  // namespace sylva::test::examples::notes
