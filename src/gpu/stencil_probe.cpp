#include "gpu/stencil_probe.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>
#include <sstream>

#include "gpu/number_text.h"
#include "io/string_reader.h"
#include "support/diagnostic.h"

namespace sylva::gpu {
namespace {

constexpr int kProbePoints = 16;  // the probe ring
constexpr int kMaxReach = 6;      // neighbours a production may read on either side

std::vector<std::string> split_modules(const std::string& text) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < text.size()) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\n')) ++at;
    std::size_t end = at;
    int depth = 0;
    while (end < text.size() && ((text[end] != ' ' && text[end] != '\n') || depth > 0)) {
      if (text[end] == '(') ++depth;
      if (text[end] == ')') --depth;
      ++end;
    }
    if (end > at) out.push_back(text.substr(at, end - at));
    at = end;
  }
  return out;
}

bool numeric_params(const ModuleTypes& types, const std::string& name) {
  const auto id = types.find(name);
  if (!id) return false;
  const auto params = types.params(*id);
  if (params.empty()) return false;
  auto scalar = [](const abi::ParamType* t) {
    return t && (t->kind == abi::ParamKind::kFloat || t->kind == abi::ParamKind::kDouble);
  };
  if (params.size() == 1 && params[0].type && params[0].type->kind == abi::ParamKind::kVector)
    return params[0].type->count >= 1 && params[0].type->count <= 4 && scalar(params[0].type->element);
  if (params.size() > 4) return false;
  for (const auto& field : params)
    if (!scalar(field.type)) return false;
  return true;
}

}  // namespace

bool parse_point_string(const std::string& text, const ModuleTypes& types, PointString& out, std::string& reason) {
  out = PointString{};
  const auto modules = split_modules(text);
  enum { kBefore, kIn, kAfter } where = kBefore;
  for (const auto& module : modules) {
    const auto open = module.find('(');
    if (open == std::string::npos) {
      if (where == kIn) where = kAfter;
      std::string& side = where == kBefore ? out.prefix : out.suffix;
      if (!side.empty()) side += ' ';
      side += module;
      continue;
    }
    const std::string name = module.substr(0, open);
    if (where == kAfter) {
      reason = "module " + name + " follows modules other than points";
      return false;
    }
    if (!out.name.empty() && name != out.name) {
      reason = "the string holds two parametric modules, " + out.name + " and " + name;
      return false;
    }
    if (out.name.empty()) {
      if (!numeric_params(types, name)) {
        reason = "module " + name + "'s parameters are not one to four float or double numbers";
        return false;
      }
      out.name = name;
    }
    std::string inner = module.substr(open + 1, module.size() - open - 2);
    const bool vector_form = inner.size() >= 2 && inner.front() == '(' && inner.back() == ')';
    if (vector_form) inner = inner.substr(1, inner.size() - 2);
    std::vector<double> values;
    const char* p = inner.data();
    const char* end = inner.data() + inner.size();
    while (p < end) {
      double v = 0;
      auto [next, error] = std::from_chars(p, end, v);
      if (error != std::errc()) {
        reason = "module " + name + "'s parameters are not numbers";
        return false;
      }
      values.push_back(v);
      p = next;
      if (p < end && *p == ',') ++p;
    }
    if (out.dim == 0) {
      out.dim = static_cast<int>(values.size());
      out.vector_form = vector_form;
    }
    if (static_cast<int>(values.size()) != out.dim || values.empty() || out.dim > 4) {
      reason = "module " + name + " has not one to four coordinates";
      return false;
    }
    out.points.insert(out.points.end(), values.begin(), values.end());
    where = kIn;
  }
  if (out.name.empty()) {
    reason = "the string holds no points (modules with float or double parameters)";
    return false;
  }
  return true;
}

std::string format_point_string(const PointString& layout, const std::vector<double>& points, bool as_float) {
  std::string out;
  out.reserve(layout.prefix.size() + layout.suffix.size() + points.size() * 12);
  out += layout.prefix;
  const std::size_t n = points.size() / layout.dim;
  for (std::size_t q = 0; q < n; ++q) {
    if (!out.empty()) out += ' ';
    out += layout.name;
    out += layout.vector_form ? "((" : "(";
    for (int d = 0; d < layout.dim; ++d) {
      if (d) out += ',';
      append_number(out, points[q * layout.dim + d], as_float);
    }
    out += layout.vector_form ? "))" : ")";
  }
  if (!layout.suffix.empty()) {
    if (!out.empty()) out += ' ';
    out += layout.suffix;
  }
  return out;
}

namespace {

// One engine step from `points` (laid out as `layout`), read back.
bool engine_step(Simulation& simulation, const PointString& layout, const std::vector<double>& points,
                 PointString& result, std::string& reason, bool ring = true) {
  try {
    const std::string text = format_point_string(layout, points, false);
    simulation.rewind();
    simulation.start_from(io::parse_string(text, simulation.types(), "<stencil probe>"));
    simulation.run(1);
  } catch (const std::exception& error) {
    reason = std::string("the production fails on probe points: ") + error.what();
    return false;
  }
  if (!parse_point_string(simulation.string_text(), simulation.types(), result, reason)) {
    reason = "after a step on probe points, " + reason;
    return false;
  }
  if (result.name != layout.name || result.dim != layout.dim || result.prefix != layout.prefix ||
      result.suffix != layout.suffix) {
    reason = "a step changes more than the points";
    return false;
  }
  const std::size_t n = points.size() / layout.dim;
  if (ring && (result.size() == 0 || result.size() % n != 0)) {
    reason = "a step of " + std::to_string(n) + " points gives " + std::to_string(result.size()) +
             ", not a fixed number per point";
    return false;
  }
  return true;
}

double scale_of(const std::vector<double>& v) {
  double m = 1;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Whether the engine's step from `points` equals the stencil's to 1e-12.
bool matches(Simulation& simulation, const PointString& layout, const std::vector<double>& points,
             const Stencil& stencil, std::string& reason) {
  PointString result;
  if (!engine_step(simulation, layout, points, result, reason, !stencil.open)) return false;
  CpuStencilDeriver cpu;
  const auto expected = cpu.derive(points, layout.dim, stencil, 1);
  if (expected.size() != result.points.size()) {
    reason = "the number of points made per point depends on the string";
    return false;
  }
  if (stencil.open && static_cast<long>(points.size() / layout.dim) < stencil.min_points()) {
    reason = "the curve has fewer points than its end rules read";
    return false;
  }
  const double tolerance = 1e-12 * scale_of(points);
  for (std::size_t i = 0; i < expected.size(); ++i)
    if (!(std::abs(expected[i] - result.points[i]) <= tolerance)) {
      reason = "the successors are not linear in the points (point " + std::to_string(i / layout.dim) +
               " differs by " + std::to_string(std::abs(expected[i] - result.points[i])) + ")";
      return false;
    }
  return true;
}


// An open curve: the whole linear map of a step on 16 points, read row by
// row from unit points; its rows in the middle repeat every k rows shifted by
// one point (the stencil), those at the ends are the end rules.
void probe_open(Simulation& simulation, ProbeResult& r) {
  const int dim = r.axiom.dim;
  const PointString& layout = r.axiom;
  constexpr int n = kProbePoints;
  PointString out;
  std::vector<double> points(static_cast<std::size_t>(n) * dim, 0.0);
  if (!engine_step(simulation, layout, points, out, r.reason, false)) return;
  const long rows = static_cast<long>(out.size());
  for (double v : out.points)
    if (v != 0) {
      r.reason = "the successors of zero points are not zero (a constant term)";
      return;
    }
  std::vector<double> longer(static_cast<std::size_t>(n + 1) * dim, 0.0);
  if (!engine_step(simulation, layout, longer, out, r.reason, false)) return;
  const long k = static_cast<long>(out.size()) - rows;
  if (k < 1 || k > 16) {
    r.reason = "a point more makes " + std::to_string(k) + " points more";
    return;
  }
  // a[row][column]
  std::vector<double> a(static_cast<std::size_t>(rows) * n, 0.0);
  for (int column = 0; column < n; ++column)
    for (int d = 0; d < dim; ++d) {
      std::fill(points.begin(), points.end(), 0.0);
      points[static_cast<std::size_t>(column) * dim + d] = 1;
      if (!engine_step(simulation, layout, points, out, r.reason, false)) return;
      if (static_cast<long>(out.size()) != rows) {
        r.reason = "the number of points made depends on their values";
        return;
      }
      for (long row = 0; row < rows; ++row)
        for (int e = 0; e < dim; ++e) {
          const double v = out.points[static_cast<std::size_t>(row) * dim + e];
          double& c = a[static_cast<std::size_t>(row) * n + column];
          if (e != d) {
            if (v != 0) {
              r.reason = "a coordinate of a successor depends on another coordinate";
              return;
            }
          } else if (d == 0) {
            c = v;
          } else if (c != v) {
            r.reason = "the coordinates are combined with different weights";
            return;
          }
        }
    }
  auto at = [&](long row, int column) {
    return column < 0 || column >= n ? 0.0 : a[static_cast<std::size_t>(row) * n + column];
  };
  // Whether block `other` (k rows from row other) is block `base` shifted by `shift` points.
  auto repeats = [&](long base, long other, int shift) {
    if (other < 0 || other + k > rows) return false;
    for (long i = 0; i < k; ++i)
      for (int column = -n; column < 2 * n; ++column)
        if (at(other + i, column + shift) != at(base + i, column)) return false;
    return true;
  };
  const int q0 = n / 2;
  const long r0 = k * q0 + (rows - k * n) / 2;
  if (r0 < 0 || r0 + k > rows) {
    r.reason = "too few points are made to find the stencil";
    return;
  }
  int down = 0, up = 0;
  while (repeats(r0, r0 - k * (down + 1), -(down + 1))) ++down;
  while (repeats(r0, r0 + k * (up + 1), up + 1)) ++up;
  Stencil& s = r.stencil;
  s.open = true;
  s.k = static_cast<int>(k);
  s.head_points = q0 - down;
  s.head_rows = static_cast<int>(r0 - k * down);
  s.tail_points = n - 1 - (q0 + up);
  s.tail_rows = static_cast<int>(rows - (r0 + k * (up + 1)));
  // The stencil: block r0 about point q0.
  int lo = n, hi = -1;
  for (long i = 0; i < k; ++i)
    for (int column = 0; column < n; ++column)
      if (at(r0 + i, column) != 0) {
        lo = std::min(lo, column - q0);
        hi = std::max(hi, column - q0);
      }
  if (hi < lo) lo = hi = 0;
  s.left = std::max(-lo, 0);
  s.right = std::max(hi, 0);
  if (s.left > kMaxReach || s.right > kMaxReach) {
    r.reason = "a successor reads neighbours more than " + std::to_string(kMaxReach) + " points away";
    return;
  }
  s.c.assign(static_cast<std::size_t>(k) * s.width(), 0.0);
  for (long i = 0; i < k; ++i)
    for (int off = -s.left; off <= s.right; ++off) s.c[i * s.width() + off + s.left] = at(r0 + i, q0 + off);
  // The end rules.
  int head_reach = s.head_points, tail_reach = s.tail_points;
  for (long row = 0; row < s.head_rows; ++row)
    for (int column = 0; column < n; ++column)
      if (at(row, column) != 0) head_reach = std::max(head_reach, column + 1);
  for (long row = rows - s.tail_rows; row < rows; ++row)
    for (int column = 0; column < n; ++column)
      if (at(row, column) != 0) tail_reach = std::max(tail_reach, n - column);
  s.end_width = std::max(head_reach, tail_reach);
  if (s.end_width > n / 2 - 1) {
    r.reason = "the rules at the ends read more than " + std::to_string(n / 2 - 1) + " points";
    return;
  }
  s.head.assign(static_cast<std::size_t>(s.head_rows) * s.end_width, 0.0);
  s.tail.assign(static_cast<std::size_t>(s.tail_rows) * s.end_width, 0.0);
  for (long row = 0; row < s.head_rows; ++row)
    for (int j = 0; j < s.end_width; ++j) s.head[row * s.end_width + j] = at(row, j);
  for (long row = 0; row < s.tail_rows; ++row)
    for (int j = 0; j < s.end_width; ++j)
      s.tail[row * s.end_width + j] = at(rows - s.tail_rows + row, n - s.end_width + j);

  std::mt19937_64 random(54321);
  std::uniform_real_distribution<double> value(-10, 10);
  for (int size : {n, n + 1, n + 7}) {
    std::vector<double> trial(static_cast<std::size_t>(size) * dim);
    for (auto& p : trial) p = value(random);
    if (!matches(simulation, layout, trial, s, r.reason)) return;
  }
  if (static_cast<long>(r.axiom.size()) < s.min_points()) {
    r.reason = "the curve has fewer points (" + std::to_string(r.axiom.size()) + ") than its end rules read (" +
               std::to_string(s.min_points()) + ")";
    return;
  }
  if (!matches(simulation, layout, r.axiom.points, s, r.reason)) {
    r.reason = "on the model's own axiom, " + r.reason;
    return;
  }
  r.in_class = true;
}

}  // namespace

ProbeResult probe_stencil(Simulation& simulation) {
  ProbeResult r;
  const auto& descriptor = simulation.descriptor();
  const bool ring = descriptor.ring && descriptor.ring();
  try {
    simulation.rewind();
    simulation.begin();
  } catch (const std::exception& error) {
    r.reason = std::string("the axiom fails: ") + error.what();
    return r;
  }
  if (!parse_point_string(simulation.string_text(), simulation.types(), r.axiom, r.reason)) {
    if (!ring) r.reason = "not a ring L-system, nor an open curve: " + r.reason;
    return r;
  }
  if (!ring) {
    probe_open(simulation, r);
    if (!r.in_class) r.reason = "not a ring L-system, nor an open curve: " + r.reason;
    return r;
  }
  const int dim = r.axiom.dim;
  PointString layout = r.axiom;

  // The zero ring: no constant term.
  std::vector<double> points(static_cast<std::size_t>(kProbePoints) * dim, 0.0);
  PointString out;
  if (!engine_step(simulation, layout, points, out, r.reason)) return r;
  const int k = static_cast<int>(out.size() / kProbePoints);
  for (double v : out.points)
    if (v != 0) {
      r.reason = "the successors of zero points are not zero (a constant term)";
      return r;
    }

  // Unit points in each coordinate: the coefficients, by offset -7 .. 8.
  const int m = kProbePoints / 2;
  std::vector<double> coefficient(static_cast<std::size_t>(k) * kProbePoints, 0.0);  // [i][offset + m]
  for (int d = 0; d < dim; ++d) {
    std::fill(points.begin(), points.end(), 0.0);
    points[static_cast<std::size_t>(m) * dim + d] = 1;
    if (!engine_step(simulation, layout, points, out, r.reason)) return r;
    if (static_cast<int>(out.size()) != k * kProbePoints) {
      r.reason = "the number of points made per point depends on their values";
      return r;
    }
    for (int q = 0; q < kProbePoints; ++q)
      for (int i = 0; i < k; ++i)
        for (int e = 0; e < dim; ++e) {
          const double v = out.points[(static_cast<std::size_t>(q) * k + i) * dim + e];
          double& c = coefficient[static_cast<std::size_t>(i) * kProbePoints + (m - q) + m - 1];
          if (e != d) {
            if (v != 0) {
              r.reason = "a coordinate of a successor depends on another coordinate";
              return r;
            }
          } else if (d == 0) {
            c = v;
          } else if (c != v) {
            r.reason = "the coordinates are combined with different weights";
            return r;
          }
        }
  }
  // The reach: offsets with a nonzero weight. Index o holds offset o - m + 1.
  int lo = kProbePoints, hi = -1;
  for (int i = 0; i < k; ++i)
    for (int o = 0; o < kProbePoints; ++o)
      if (coefficient[static_cast<std::size_t>(i) * kProbePoints + o] != 0) {
        lo = std::min(lo, o);
        hi = std::max(hi, o);
      }
  if (hi < 0) lo = hi = m - 1;  // every weight zero: reads the point alone
  const int left = -(lo - m + 1), right = hi - m + 1;
  if (left > kMaxReach || right > kMaxReach || left < 0 || right < 0) {
    // A weight on the far side only (left < 0) is still a stencil; widen to include the point.
    if (left > kMaxReach || right > kMaxReach) {
      r.reason = "a successor reads neighbours more than " + std::to_string(kMaxReach) + " points away";
      return r;
    }
  }
  Stencil& s = r.stencil;
  s.k = k;
  s.left = std::max(left, 0);
  s.right = std::max(right, 0);
  s.c.assign(static_cast<std::size_t>(k) * s.width(), 0.0);
  for (int i = 0; i < k; ++i)
    for (int off = -s.left; off <= s.right; ++off)
      s.c[static_cast<std::size_t>(i) * s.width() + off + s.left] =
          coefficient[static_cast<std::size_t>(i) * kProbePoints + off + m - 1];

  // Random rings, and the model's own axiom: the production is that map.
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> value(-10, 10);
  for (int trial = 0; trial < 3; ++trial) {
    for (auto& p : points) p = value(random);
    if (!matches(simulation, layout, points, s, r.reason)) return r;
  }
  if (static_cast<int>(r.axiom.size()) < s.width()) {
    r.reason = "the ring has fewer points (" + std::to_string(r.axiom.size()) + ") than the production reads (" +
               std::to_string(s.width()) + ")";
    return r;
  }
  if (!matches(simulation, layout, r.axiom.points, s, r.reason)) {
    r.reason = "on the model's own axiom, " + r.reason;
    return r;
  }
  r.in_class = true;
  return r;
}

}  // namespace sylva::gpu
