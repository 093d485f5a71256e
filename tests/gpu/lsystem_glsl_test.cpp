// L-systems on the GPU by algorithm 2 (gpu/lsystem_glsl.h): the productions
// translated to GLSL and to a CPU interpreter; the CPU interpreter equals the
// engine to rounding, the GL deriver (OSMesa) gives the engine's modules
// exactly and its numbers to float precision; the scan-add pass equals
// std::exclusive_scan; models outside the class are refused with the reason
// and its place.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "gpu/lsystem_glsl.h"
#include "io/string_reader.h"
#include "lstring/module_string.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using gpu::GpuString;
using gpu::LsystemTranslation;

const std::string kAdaptive = "adaptive-subdivision/adaptive-subdivision.l";

build::BuildOptions test_build(std::vector<std::string> defines = {}) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.defines = std::move(defines);
  return options;
}

LsystemTranslation translate(const std::string& model, std::vector<std::string> defines = {}) {
  const auto build = test_build(std::move(defines));
  Simulation simulation(model, build);
  return gpu::translate_lsystem(simulation, build);
}

// A string as names and numbers: the engine's, or a GpuString's.
struct Module {
  std::string name;
  std::vector<double> numbers;
};

std::vector<Module> engine_modules(const Simulation& simulation) {
  std::vector<Module> out;
  const ModuleString& s = simulation.string();
  const ModuleTypes& types = simulation.types();
  for (std::size_t at = 0; at < s.size_bytes(); at += types.encoded_size(module_id_at(s.data(), at))) {
    const ModuleId id = module_id_at(s.data(), at);
    out.push_back({types.name(id), types.numbers(id, module_params(s.data(), at))});
  }
  return out;
}

std::vector<Module> gpu_modules(const gpu::LsystemProgram& program, const GpuString& s) {
  std::vector<Module> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& type = program.types[static_cast<std::size_t>(s.types[i])];
    out.push_back({type.name, std::vector<double>(s.params.begin() + 4 * i, s.params.begin() + 4 * i + type.floats)});
  }
  return out;
}

// Same modules in the same order; numbers within `relative` of the largest.
void expect_same(const std::vector<Module>& got, const std::vector<Module>& want, double relative) {
  ASSERT_EQ(got.size(), want.size());
  double scale = 1;
  for (const Module& m : want)
    for (double v : m.numbers) scale = std::max(scale, std::abs(v));
  double worst = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].name, want[i].name) << "module " << i;
    ASSERT_EQ(got[i].numbers.size(), want[i].numbers.size()) << "module " << i;
    for (std::size_t k = 0; k < got[i].numbers.size(); ++k)
      worst = std::max(worst, std::abs(got[i].numbers[k] - want[i].numbers[k]));
  }
  EXPECT_LE(worst, relative * scale);
}

TEST(LsystemGlsl, TranslatesTheAdaptiveSubdivision) {
  const auto t = translate(example_path(kAdaptive));
  ASSERT_TRUE(t.in_class) << t.reason;
  EXPECT_EQ(t.program.productions, 6);
  EXPECT_FALSE(t.program.ring);
  ASSERT_EQ(t.axiom.size(), 10u);
  const auto& e = t.program.types[static_cast<std::size_t>(t.axiom.types[0])];
  const auto& p = t.program.types[static_cast<std::size_t>(t.axiom.types[1])];
  EXPECT_EQ(e.name, "E");
  EXPECT_EQ(p.name, "P");
  EXPECT_EQ(p.floats, 3);  // V2d and int
  EXPECT_NE(t.program.glsl.find("int sylva_match(int i, out int len)"), std::string::npos);
}

// The variants of the example: L-system 5 at two thresholds, with the
// production that keeps flat runs, and L-system 3.
const std::vector<std::vector<std::string>> kVariants = {
    {}, {"THRESHOLD=0.025"}, {"KEEP_FLAT"}, {"LSYSTEM3"}};

TEST(LsystemGlsl, CpuInterpreterEqualsTheEngine) {
  for (const auto& defines : kVariants) {
    const auto t = translate(example_path(kAdaptive), defines);
    ASSERT_TRUE(t.in_class) << t.reason;
    Simulation simulation(example_path(kAdaptive), test_build(defines));
    gpu::CpuLsystemDeriver cpu;
    for (int steps = 1; steps <= 5; ++steps) {
      simulation.rewind();
      simulation.run(steps);
      SCOPED_TRACE(testing::Message() << (defines.empty() ? "" : defines[0]) << ", " << steps << " steps");
      expect_same(gpu_modules(t.program, cpu.derive(t.program, t.axiom, steps)), engine_modules(simulation), 1e-12);
    }
  }
}

// No point of the strings the productions read is within float rounding of
// the threshold: the GPU takes the engine's branch of p3 everywhere.
double closest_to_threshold(const std::vector<Module>& string, double threshold) {
  double closest = 1e300;
  for (std::size_t i = 1; i + 1 < string.size(); ++i) {
    if (string[i - 1].name != "P" || string[i].name != "P" || string[i + 1].name != "P") continue;
    const auto& l = string[i - 1].numbers;
    const auto& v = string[i].numbers;
    const auto& r = string[i + 1].numbers;
    const double d = std::hypot(v[0] - (l[0] + r[0]) / 2, v[1] - (l[1] + r[1]) / 2);
    closest = std::min(closest, std::abs(d - threshold));
  }
  return closest;
}

TEST(LsystemGlsl, GlDeriverEqualsTheEngineToFloatPrecision) {
  for (const auto& defines : kVariants) {
    const auto t = translate(example_path(kAdaptive), defines);
    ASSERT_TRUE(t.in_class) << t.reason;
    const double threshold = defines.empty() || defines[0] == "KEEP_FLAT" ? 0.05 : 0.025;
    Simulation simulation(example_path(kAdaptive), test_build(defines));
    for (int steps = 1; steps <= 5; ++steps) {
      SCOPED_TRACE(testing::Message() << (defines.empty() ? "" : defines[0]) << ", " << steps << " steps");
      simulation.rewind();
      simulation.run(steps - 1);
      // The curve spans 6 units: float rounding is about 1e-6 there.
      if (defines.empty() || defines[0] != "LSYSTEM3") {
        EXPECT_GT(closest_to_threshold(engine_modules(simulation), threshold), 1e-4);
      }
      simulation.rewind();
      simulation.run(steps);
      const GpuString derived = gpu::gl_lsystem_deriver().derive(t.program, t.axiom, steps);
      expect_same(gpu_modules(t.program, derived), engine_modules(simulation), 1e-5);
    }
  }
}

TEST(LsystemGlsl, GlDeriverWrapsStringsIntoRows) {
  // Rows of 7 texels: the string, the sums and the successors cross rows.
  const auto t = translate(example_path(kAdaptive));
  ASSERT_TRUE(t.in_class) << t.reason;
  gpu::CpuLsystemDeriver cpu;
  auto& gl = gpu::gl_lsystem_deriver();
  for (int radix : {2, 8}) {
    gl.set_layout(7, radix);
    const GpuString derived = gl.derive(t.program, t.axiom, 5);
    gl.set_layout(0, 2);
    expect_same(gpu_modules(t.program, derived), gpu_modules(t.program, cpu.derive(t.program, t.axiom, 5)), 1e-5);
  }
}

// A ring whose productions give 0, 1 or 3 modules by the values, with
// locals, if/else, a ternary, int arithmetic and vector functions.
const char* const kRingModel = R"(#include <lpfgall.h>
module Q(V3d, int);
module M(float, bool);
ring L-system: 1;
derivation length: 4;
const double kScale = 0.5;
Axiom: Q(V3d(1, 0, 0), 0) M(2, true) Q(V3d(0, 1, 0), 1) Q(V3d(0, 0, 1), 2) M(-1, false) Q(V3d(1, 1, 1), 3);
Q(a, i) < M(x, b) > Q(c, j) : {
  double s = x * kScale;
  if (b && (a % c).Length() > 0.1) produce M(s, !b) Q(Normalize(a + c), i + j) M(-s, b);
  else if (x < 0) produce;
  produce M(fabs(x) + 1, x > 0 ? true : false);
}
Q(a, i) > Q(c, j) : {
  V3d m = (a + c) / 2;
  m.z += 0.25;
  int k = (i * 3 + j) % 5;
  if (k == 0) produce;
  produce Q(a, k) Q(m * kScale, k - 1);
}
M(x, b) < Q(a, i) : { produce Q(V3d(a.x, a.y + x, sqrt(a * a)), i); }
)";

TEST(LsystemGlsl, DerivesARingWithSuccessorsOfEveryLength) {
  const auto model = write_temp_file("gpu2-ring", "ring.l", kRingModel);
  const auto t = translate(model);
  ASSERT_TRUE(t.in_class) << t.reason;
  EXPECT_TRUE(t.program.ring);
  Simulation simulation(model, test_build());
  gpu::CpuLsystemDeriver cpu;
  for (int steps = 1; steps <= 4; ++steps) {
    SCOPED_TRACE(testing::Message() << steps << " steps");
    simulation.rewind();
    simulation.run(steps);
    const auto want = engine_modules(simulation);
    expect_same(gpu_modules(t.program, cpu.derive(t.program, t.axiom, steps)), want, 1e-12);
    expect_same(gpu_modules(t.program, gpu::gl_lsystem_deriver().derive(t.program, t.axiom, steps)), want, 1e-5);
  }
}

TEST(LsystemGlsl, ScanAddEqualsExclusiveScan) {
  auto& gl = gpu::gl_lsystem_deriver();
  std::mt19937 random(7);
  for (int radix : {2, 3, 8}) {
    for (int n : {1, 2, 3, 5, 64, 65, 100, 1000, 4097}) {
      std::vector<std::int32_t> lengths(static_cast<std::size_t>(n));
      for (auto& l : lengths) l = static_cast<std::int32_t>(random() % 5);  // 0 .. 4: empty successors too
      std::vector<std::int64_t> want(lengths.size());
      std::exclusive_scan(lengths.begin(), lengths.end(), want.begin(), std::int64_t{0});
      gl.set_layout(64, radix);  // several rows from n = 65 on
      const auto got = gl.scan_add(lengths);
      gl.set_layout(0, 2);
      EXPECT_EQ(got, want) << "n = " << n << ", radix " << radix;
    }
  }
}

// ---- refused, with the reason and its place ----------------------------------

std::string model_with(const std::string& production) {
  return "#include <lpfgall.h>\n"   // 1
         "module P(double);\n"      // 2
         "derivation length: 2;\n"  // 3
         "Axiom: P(1) P(2) P(3);\n" // 4
         + production + "\n";       // 5
}

TEST(LsystemGlsl, RefusesAnUnsupportedCall) {
  const auto model = write_temp_file("gpu2-call", "call.l", model_with("P(v) : { produce P(erf(v)); }"));
  const auto t = translate(model);
  EXPECT_FALSE(t.in_class);
  EXPECT_EQ(t.reason.rfind(model + ":5:20: a call to erf, which is not translated to GLSL", 0), 0u) << t.reason;
}

TEST(LsystemGlsl, RefusesNewContext) {
  const auto model = write_temp_file("gpu2-new", "new.l", model_with("P(vl) << P(v) : { produce P(vl + v); }"));
  const auto t = translate(model);
  EXPECT_FALSE(t.in_class);
  EXPECT_EQ(t.reason, model + ":5:1: new context (<< or >>): the GPU reads only the old string");
}

TEST(LsystemGlsl, RefusesAStochasticBody) {
  const auto model = write_temp_file("gpu2-ran", "ran.l",
                                     model_with("P(v) : {\n  if (ran(1) < 0.5) produce P(v) P(v);\n}"));
  const auto t = translate(model);
  EXPECT_FALSE(t.in_class);
  EXPECT_EQ(t.reason, model + ":6:7: stochastic: ran draws random numbers");
}

TEST(LsystemGlsl, RefusesDecompositionRules) {
  const auto t = translate(example_path("four-point/four-point.l"), {"OPEN"});
  EXPECT_FALSE(t.in_class);
  EXPECT_NE(t.reason.find("a decomposition rule"), std::string::npos) << t.reason;
}

// ---- sylva run --gpu ------------------------------------------------------------

TEST(LsystemGpuCommand, WritesTheEnginesString) {
  const auto gpu_run = run_sylva({"run", example_path(kAdaptive), "--gpu"});
  ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("by its productions translated to GLSL (algorithm 2)"), std::string::npos) << gpu_run.err;
  const auto cpu_run = run_sylva({"run", example_path(kAdaptive)});
  ASSERT_EQ(cpu_run.exit_code, 0) << cpu_run.err;
  // Both read back as the model's modules, the same ones, numbers to float precision.
  Simulation simulation(example_path(kAdaptive), test_build());
  auto read = [&](const std::string& text) {
    simulation.rewind();
    simulation.start_from(io::parse_string(text, simulation.types(), "<string>"));
    simulation.begin();
    return engine_modules(simulation);
  };
  expect_same(read(gpu_run.out), read(cpu_run.out), 1e-5);
}

TEST(LsystemGpuCommand, SaysWhyNeitherAlgorithmApplies) {
  const auto model = write_temp_file("gpu2-why", "why.l", model_with("P(v) : { produce P(erf(v)); }"));
  const auto gpu_run = run_sylva({"run", model, "--gpu"});
  ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("is not a point-subdivision L-system: "), std::string::npos) << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("; nor an L-system whose productions translate to GLSL: " + model +
                             ":5:20: a call to erf"),
            std::string::npos)
      << gpu_run.err;
  EXPECT_NE(gpu_run.err.find("; deriving on the CPU"), std::string::npos);
  EXPECT_EQ(gpu_run.out, run_sylva({"run", model}).out);
}

}  // namespace
}  // namespace sylva::test
