// Helpers for the tests of examples/cpfg/: reading cpfg's string format back
// into modules (one symbol character, optionally followed by (p1,p2,...)),
// deriving an example or a modified copy of it, and a second, plain C++
// implementation of the Anabaena cell lineage.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::cpfg_examples {

struct CpfgModule {
  char name = 0;
  std::vector<double> params;
};

// cpfg's format: modules concatenated, a module is one character optionally
// followed by a parenthesised, comma-separated list of numbers.
inline std::vector<CpfgModule> parse_cpfg(const std::string& text) {
  std::vector<CpfgModule> out;
  std::size_t i = 0;
  while (i < text.size()) {
    char c = text[i++];
    if (c == ' ' || c == '\n') continue;
    CpfgModule m;
    m.name = c;
    if (i < text.size() && text[i] == '(') {
      std::size_t close = text.find(')', i);
      std::string inside = text.substr(i + 1, close - i - 1);
      std::size_t pos = 0;
      while (pos <= inside.size()) {
        std::size_t comma = inside.find(',', pos);
        if (comma == std::string::npos) comma = inside.size();
        m.params.push_back(std::strtod(inside.substr(pos, comma - pos).c_str(), nullptr));
        pos = comma + 1;
      }
      i = close + 1;
    }
    out.push_back(m);
  }
  return out;
}

inline int count(const std::vector<CpfgModule>& s, char name) {
  int n = 0;
  for (const CpfgModule& m : s) n += m.name == name;
  return n;
}

inline std::string model(const std::string& name) { return example_path("cpfg/" + name + "/" + name + ".l"); }

// A copy of example `name` with each `from` replaced by `to` (each must occur),
// written to a fresh temporary directory; returns the copy's path.
inline std::string modified_copy(const std::string& name, const std::vector<std::pair<std::string, std::string>>& edits,
                                 const std::string& tag) {
  std::string text = read_text(model(name));
  for (const auto& [from, to] : edits) {
    std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from << " not in " << name;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const std::string path = (std::filesystem::path(make_temp_dir("cpfg-" + tag)) / (name + ".l")).string();
  std::ofstream(path) << text;
  return path;
}

// ---- the Anabaena lineage in continuous time, solved in closed form -------
// A cell of initial age a0 (0 for a short cell, 0.2 for a long one) reaches
// the division age 1 after 1 - a0 time units and is then replaced by a short
// and a long cell. The number of cells at time T descending from a cell of age
// a0 at time 0 is therefore 1 if T < 1 - a0, and otherwise the sum for the two
// children at time T - (1 - a0). Times are kept in exact tenths.
// `divide_at_boundary` says whether a cell that reaches age 1 exactly at T has
// divided (true: t >= t_div, the notes' condition).
inline long cells_at(int a0_tenths, int T_tenths, bool divide_at_boundary = true) {
  const int rest = T_tenths - (10 - a0_tenths);
  if (rest > 0 || (rest == 0 && divide_at_boundary))
    return cells_at(0, rest, divide_at_boundary) + cells_at(2, rest, divide_at_boundary);
  return 1;
}

// Whether any division time of the lineage falls exactly on T.
inline bool division_exactly_at(int a0_tenths, int T_tenths) {
  const int rest = T_tenths - (10 - a0_tenths);
  if (rest == 0) return true;
  return rest > 0 && (division_exactly_at(0, rest) || division_exactly_at(2, rest));
}

}  // namespace sylva::test::cpfg_examples
