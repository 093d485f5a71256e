// Points of plane curves as the curve examples' strings print them ("(x,y)"
// for a V2d), and the dense matrices their tests build independently.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "examples/example_strings.h"

namespace sylva::test::examples {

struct Pt {
  double x = 0, y = 0;
};
inline Pt operator+(Pt a, Pt b) { return {a.x + b.x, a.y + b.y}; }
inline Pt operator-(Pt a, Pt b) { return {a.x - b.x, a.y - b.y}; }
inline Pt operator*(double k, Pt a) { return {k * a.x, k * a.y}; }
inline double norm(Pt a) { return std::hypot(a.x, a.y); }
inline double dist(Pt a, Pt b) { return norm(a - b); }

// "(x,y)" as printed for a V2d.
inline Pt read_pt(const std::string& text) {
  const std::vector<std::string> c = split_top_level(text.substr(1, text.size() - 2));
  EXPECT_EQ(c.size(), 2u) << text;
  return {number(c.at(0)), number(c.at(1))};
}

// The first parameter of every module named `name`, in string order.
inline std::vector<Pt> points(const std::vector<Module>& s, const std::string& name = "P") {
  std::vector<Pt> out;
  for (const Module& m : s)
    if (m.name == name) out.push_back(read_pt(m.params.at(0)));
  return out;
}

// A dense matrix, rows of weights on the points.
using Matrix = std::vector<std::vector<double>>;
inline Matrix zeros(std::size_t rows, std::size_t columns) { return Matrix(rows, std::vector<double>(columns, 0.0)); }

inline std::vector<Pt> multiply(const Matrix& m, const std::vector<Pt>& p) {
  std::vector<Pt> out;
  for (const std::vector<double>& row : m) {
    EXPECT_EQ(row.size(), p.size());
    Pt q;
    for (std::size_t c = 0; c < row.size() && c < p.size(); ++c) q = q + row[c] * p[c];
    out.push_back(q);
  }
  return out;
}

}  // namespace sylva::test::examples
