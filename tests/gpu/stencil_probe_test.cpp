// Point-subdivision L-systems on the GPU (gpu/): the probe finds the
// stencils of the bundled subdivision examples and rejects other models; the
// CPU stencil deriver equals the engine to 1e-12 and the GL one (OSMesa) to
// float precision; `sylva run --gpu` writes the engine's string.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "api/simulation.h"
#include "gpu/stencil_deriver.h"
#include "gpu/stencil_probe.h"
#include "gpu/gpu_test_support.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using gpu::PointString;
using gpu::ProbeResult;
using gpu::Stencil;

build::BuildOptions test_build(bool open = false) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  if (open) options.defines = {"OPEN"};
  return options;
}

ProbeResult probe(const std::string& model, bool open = false) {
  Simulation simulation(model, test_build(open));
  return gpu::probe_stencil(simulation);
}

const std::string kChaikin = "chaikin/chaikin.l";
const std::string kBspline = "cubic-bspline-subdivision/cubic-bspline-subdivision.l";
const std::string kFourPoint = "four-point/four-point.l";

Stencil closed_stencil(int k, int left, int right, std::vector<double> c) {
  Stencil s;
  s.k = k;
  s.left = left;
  s.right = right;
  s.c = std::move(c);
  return s;
}

void expect_stencil(const Stencil& s, int k, int left, int right, const std::vector<double>& c) {
  EXPECT_EQ(s.k, k);
  EXPECT_EQ(s.left, left);
  EXPECT_EQ(s.right, right);
  ASSERT_EQ(s.c.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(s.c[i], c[i], 1e-15) << "weight " << i;
}

TEST(StencilProbe, FindsChaikinsStencil) {
  const auto r = probe(example_path(kChaikin));
  ASSERT_TRUE(r.in_class) << r.reason;
  expect_stencil(r.stencil, 2, 1, 1, {0.25, 0.75, 0, 0, 0.75, 0.25});
  EXPECT_EQ(r.axiom.name, "P");
  EXPECT_EQ(r.axiom.dim, 2);
  EXPECT_EQ(r.axiom.prefix, "Control");
  EXPECT_EQ(r.axiom.size(), 4u);
}

TEST(StencilProbe, FindsTheCubicBsplineStencil) {
  const auto r = probe(example_path(kBspline));
  ASSERT_TRUE(r.in_class) << r.reason;
  expect_stencil(r.stencil, 2, 1, 1, {0.125, 0.75, 0.125, 0, 0.5, 0.5});
}

TEST(StencilProbe, FindsTheFourPointStencil) {
  const auto r = probe(example_path(kFourPoint));
  ASSERT_TRUE(r.in_class) << r.reason;
  expect_stencil(r.stencil, 2, 1, 2, {0, 1, 0, 0, -0.0625, 0.5625, 0.5625, -0.0625});
}

TEST(StencilProbe, RejectsKoch) {
  const auto r = probe(example_path("koch/koch.l"));
  EXPECT_FALSE(r.in_class);
  EXPECT_EQ(r.reason,
            "not a ring L-system, nor an open curve: after a step on probe points, the string holds two parametric "
            "modules, F and Left");
}

// Open curves (-D OPEN): the stencil inside, rows of their own at the ends.
TEST(StencilProbe, FindsChaikinsOpenCurve) {
  const auto r = probe(example_path(kChaikin), true);
  ASSERT_TRUE(r.in_class) << r.reason;
  const Stencil& s = r.stencil;
  EXPECT_TRUE(s.open);
  expect_stencil(s, 2, 1, 1, {0.25, 0.75, 0, 0, 0.75, 0.25});
  EXPECT_EQ(s.head_points, 1);
  EXPECT_EQ(s.tail_points, 1);
  EXPECT_EQ(s.head_rows, 2);
  EXPECT_EQ(s.tail_rows, 2);
  ASSERT_EQ(s.end_width, 2);
  EXPECT_EQ(s.head, (std::vector<double>{1, 0, 0.75, 0.25}));
  EXPECT_EQ(s.tail, (std::vector<double>{0.25, 0.75, 0, 1}));
}

TEST(StencilProbe, FindsTheOpenCubicBspline) {
  const auto r = probe(example_path(kBspline), true);
  ASSERT_TRUE(r.in_class) << r.reason;
  const Stencil& s = r.stencil;
  expect_stencil(s, 2, 1, 1, {0.125, 0.75, 0.125, 0, 0.5, 0.5});
  EXPECT_EQ(s.head_rows, 2);  // P(v) P(v/2 + vr/2)
  EXPECT_EQ(s.tail_rows, 1);  // P(v)
  EXPECT_EQ(r.axiom.prefix, "Control E");
  EXPECT_EQ(r.axiom.suffix, "E");
}

TEST(StencilProbe, FindsTheOpenFourPoint) {
  const auto r = probe(example_path(kFourPoint), true);
  ASSERT_TRUE(r.in_class) << r.reason;
  EXPECT_TRUE(r.stencil.open);
  EXPECT_EQ(r.stencil.successors(6), 11);
}

std::string ring_model(const std::string& production) {
  return "#include <lpfgall.h>\n"
         "module P(double);\n"
         "ring L-system: 1;\n"
         "derivation length: 2;\n"
         "Axiom: P(1) P(2) P(3) P(4) P(5);\n" +
         production + "\n";
}

TEST(StencilProbe, RejectsANonLinearBody) {
  const auto model = write_temp_file("gpu-nonlinear", "square.l",
                                     ring_model("P(l) < P(v) > P(r) : { produce P(v * v) P(0.5 * (l + r)); }"));
  const auto r = probe(model);
  EXPECT_FALSE(r.in_class);
  EXPECT_NE(r.reason.find("not linear"), std::string::npos) << r.reason;
}

TEST(StencilProbe, RejectsAConstantTerm) {
  const auto model =
      write_temp_file("gpu-constant", "shift.l", ring_model("P(l) < P(v) > P(r) : { produce P(v + 1); }"));
  const auto r = probe(model);
  EXPECT_FALSE(r.in_class);
  EXPECT_NE(r.reason.find("constant term"), std::string::npos) << r.reason;
}

TEST(StencilProbe, RejectsAValueDependentCount) {
  const auto model = write_temp_file(
      "gpu-count", "split.l", ring_model("P(v) : { if (v > 2.5) produce P(v) P(v); else produce P(v); }"));
  const auto r = probe(model);
  EXPECT_FALSE(r.in_class);
  EXPECT_FALSE(r.reason.empty());
}

TEST(StencilProbe, AcceptsAScalarRing) {
  const auto model =
      write_temp_file("gpu-scalar", "mean.l", ring_model("P(l) < P(v) > P(r) : { produce P(0.5 * (l + r)); }"));
  const auto r = probe(model);
  ASSERT_TRUE(r.in_class) << r.reason;
  expect_stencil(r.stencil, 1, 1, 1, {0.5, 0, 0.5});
  EXPECT_EQ(r.axiom.dim, 1);
}

// The engine's string after `steps` steps, as points.
PointString engine_points(const std::string& model, int steps, bool open = false) {
  Simulation simulation(model, test_build(open));
  simulation.run(steps);
  PointString points;
  std::string reason;
  EXPECT_TRUE(gpu::parse_point_string(simulation.string_text(), simulation.types(), points, reason)) << reason;
  return points;
}

// The example and whether -D OPEN.
class Examples : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(Examples, CpuStencilDeriverEqualsTheEngine) {
  const auto& [model, open] = GetParam();
  const auto r = probe(example_path(model), open);
  ASSERT_TRUE(r.in_class) << r.reason;
  gpu::CpuStencilDeriver cpu;
  const auto derived = cpu.derive(r.axiom.points, r.axiom.dim, r.stencil, 6);
  expect_close(derived, engine_points(example_path(model), 6, open).points, 1e-12);
}

TEST_P(Examples, GlStencilDeriverEqualsTheEngineToFloatPrecision) {
  const auto& [model, open] = GetParam();
  const auto r = probe(example_path(model), open);
  ASSERT_TRUE(r.in_class) << r.reason;
  const auto derived = gpu::gl_stencil_deriver().derive(r.axiom.points, r.axiom.dim, r.stencil, 6);
  expect_close(derived, engine_points(example_path(model), 6, open).points, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(StencilExamples, Examples,
                         ::testing::Combine(::testing::Values(kChaikin, kBspline, kFourPoint),
                                            ::testing::Bool()));

TEST(GlStencilDeriver, WrapsLargeRingsIntoRows) {
  // 5000 points around a circle, 3 steps: 40000 texels, several rows.
  std::vector<double> points;
  for (int i = 0; i < 5000; ++i) {
    const double a = 2 * M_PI * i / 5000;
    points.push_back(10 * std::cos(a));
    points.push_back(10 * std::sin(a));
  }
  Stencil chaikin = closed_stencil(2, 1, 1, {0.25, 0.75, 0, 0, 0.75, 0.25});
  gpu::CpuStencilDeriver cpu;
  expect_close(gpu::gl_stencil_deriver().derive(points, 2, chaikin, 3), cpu.derive(points, 2, chaikin, 3), 1e-6);
}

TEST(GlStencilDeriver, DerivesLargeOpenCurves) {
  // Chaikin's open curve (end points kept) from 5000 points, 3 steps.
  std::vector<double> points;
  for (int i = 0; i < 5000; ++i) {
    points.push_back(i * 0.01);
    points.push_back(std::sin(i * 0.01));
  }
  Stencil open = closed_stencil(2, 1, 1, {0.25, 0.75, 0, 0, 0.75, 0.25});
  open.open = true;
  open.head_points = open.tail_points = 1;
  open.head_rows = open.tail_rows = 2;
  open.end_width = 2;
  open.head = {1, 0, 0.75, 0.25};
  open.tail = {0.25, 0.75, 0, 1};
  gpu::CpuStencilDeriver cpu;
  const auto want = cpu.derive(points, 2, open, 3);
  EXPECT_EQ(want.size(), 2u * 8 * 5000);
  expect_close(gpu::gl_stencil_deriver().derive(points, 2, open, 3), want, 1e-6);
}

TEST(GlStencilDeriver, DerivesPointsOfOneToFourCoordinates) {
  Stencil four_point = closed_stencil(2, 1, 2, {0, 1, 0, 0, -0.0625, 0.5625, 0.5625, -0.0625});
  gpu::CpuStencilDeriver cpu;
  for (int dim = 1; dim <= 4; ++dim) {
    std::vector<double> points;
    for (int i = 0; i < 7 * dim; ++i) points.push_back(std::sin(1.7 * i) * 5);
    expect_close(gpu::gl_stencil_deriver().derive(points, dim, four_point, 4),
                 cpu.derive(points, dim, four_point, 4), 1e-6);
  }
}

TEST(GpuCommand, WritesTheEnginesString) {
  const auto gpu_run = run_sylva({"run", example_path(kChaikin), "--gpu", "--steps", "3"});
  ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
  PointString got, want;
  std::string reason;
  Simulation simulation(example_path(kChaikin), test_build());
  simulation.run(3);
  std::string text = gpu_run.out;
  ASSERT_TRUE(gpu::parse_point_string(text, simulation.types(), got, reason)) << reason;
  ASSERT_TRUE(gpu::parse_point_string(simulation.string_text(), simulation.types(), want, reason)) << reason;
  EXPECT_EQ(got.prefix, "Control");
  expect_close(got.points, want.points, 1e-6);
}

// Koch's snowflake is no stencil, but its productions translate to GLSL:
// the GPU derives it by algorithm 2 and says so; the string is the engine's.
TEST(GpuCommand, ANonStencilModelSaysWhyAndRunsByItsTranslatedProductions) {
  const auto gpu_run = run_sylva({"run", example_path("koch/koch.l"), "--gpu", "--steps", "2"});
  ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("is not a point-subdivision L-system: not a ring L-system, nor an open curve: "),
            std::string::npos)
      << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("deriving it on the GPU by its productions translated to GLSL"), std::string::npos)
      << gpu_run.err;
  const auto cpu_run = run_sylva({"run", example_path("koch/koch.l"), "--steps", "2"});
  EXPECT_EQ(gpu_run.out, cpu_run.out);
}

}  // namespace
}  // namespace sylva::test
