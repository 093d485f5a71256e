// The GPU derivers' OpenGL (render/gl_headless_context.h): SYLVA_GL=osmesa
// and SYLVA_GL=egl (on a machine without a GPU, Mesa's surfaceless platform:
// llvmpipe) both give the engine's points and modules to float precision,
// and so each other's; each deriver says which it ran on; any other SYLVA_GL
// is an error that names it. The other GPU tests run under whichever the
// environment chooses (unset: EGL where it makes a context): run them with
// SYLVA_GL=osmesa and SYLVA_GL=egl for both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "gpu/lsystem_glsl.h"
#include "gpu/stencil_deriver.h"
#include "gpu/stencil_probe.h"
#include "support/diagnostic.h"
#include "gpu/gpu_test_support.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// SYLVA_GL for the scope (unset for nullptr).
class ScopedGl {
 public:
  explicit ScopedGl(const char* value) {
    if (const char* old = std::getenv("SYLVA_GL")) old_ = old;
    value ? setenv("SYLVA_GL", value, 1) : unsetenv("SYLVA_GL");
  }
  ~ScopedGl() { old_ ? setenv("SYLVA_GL", old_->c_str(), 1) : unsetenv("SYLVA_GL"); }
  ScopedGl(const ScopedGl&) = delete;
  ScopedGl& operator=(const ScopedGl&) = delete;

 private:
  std::optional<std::string> old_;
};

const char* const kBackends[] = {"osmesa", "egl"};

// What the derivers' name() starts with after running on `backend`.
std::string named(const std::string& backend) { return backend == "egl" ? "OpenGL on EGL " : "OpenGL on OSMesa: "; }

build::BuildOptions test_build() {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  return options;
}

TEST(GpuOpenGl, EglAndOsmesaDeriveTheEnginesPoints) {
  const std::string model = example_path("four-point/four-point.l");
  Simulation simulation(model, test_build());
  const gpu::ProbeResult probe = gpu::probe_stencil(simulation);
  ASSERT_TRUE(probe.in_class) << probe.reason;
  simulation.rewind();
  simulation.run(6);
  gpu::PointString engine;
  std::string reason;
  ASSERT_TRUE(gpu::parse_point_string(simulation.string_text(), simulation.types(), engine, reason)) << reason;

  std::vector<std::vector<double>> derived;
  for (const char* backend : kBackends) {
    SCOPED_TRACE(backend);
    ScopedGl gl(backend);
    auto& deriver = gpu::gl_stencil_deriver();
    derived.push_back(deriver.derive(probe.axiom.points, probe.axiom.dim, probe.stencil, 6));
    expect_close(derived.back(), engine.points, 1e-6);
    EXPECT_EQ(deriver.name().rfind(named(backend), 0), 0u) << deriver.name();
    std::printf("SYLVA_GL=%s: %s\n", backend, deriver.name().c_str());
  }
  expect_close(derived[1], derived[0], 1e-6);
}

TEST(GpuOpenGl, EglAndOsmesaDeriveTheEnginesModules) {
  const std::string model = example_path("adaptive-subdivision/adaptive-subdivision.l");
  Simulation simulation(model, test_build());
  const gpu::LsystemTranslation t = gpu::translate_lsystem(simulation, test_build());
  ASSERT_TRUE(t.in_class) << t.reason;
  // The CPU interpreter equals the engine to rounding (lsystem_glsl_test.cpp).
  const gpu::GpuString want = gpu::CpuLsystemDeriver().derive(t.program, t.axiom, 5);
  const std::vector<std::int32_t> lengths = {3, 0, 1, 4, 2, 0, 0, 5, 1, 1, 2, 3, 0, 4};
  std::vector<std::vector<std::int64_t>> sums;
  for (const char* backend : kBackends) {
    SCOPED_TRACE(backend);
    ScopedGl gl(backend);
    auto& deriver = gpu::gl_lsystem_deriver();
    const gpu::GpuString got = deriver.derive(t.program, t.axiom, 5);
    EXPECT_EQ(got.types, want.types);
    expect_close(got.params, want.params, 1e-5);
    EXPECT_EQ(deriver.name().rfind(named(backend), 0), 0u) << deriver.name();
    sums.push_back(deriver.scan_add(lengths));
  }
  EXPECT_EQ(sums[0], sums[1]);
}

// Unset, EGL where it makes a context (here: whether SYLVA_GL=egl does), else OSMesa.
TEST(GpuOpenGl, TheDefaultIsEglWhereItMakesAContext) {
  auto& deriver = gpu::gl_lsystem_deriver();
  const std::vector<std::int32_t> lengths = {1, 2, 3};
  bool egl = true;
  {
    ScopedGl gl("egl");
    try {
      deriver.scan_add(lengths);
    } catch (const ModelError& error) {
      egl = false;
      std::printf("SYLVA_GL=egl: %s\n", error.what());
    }
  }
  ScopedGl gl(nullptr);
  EXPECT_EQ(deriver.scan_add(lengths), (std::vector<std::int64_t>{0, 1, 3}));
  EXPECT_EQ(deriver.name().rfind(named(egl ? "egl" : "osmesa"), 0), 0u) << deriver.name();
}

TEST(GpuOpenGl, TheGpuCommandWritesTheEnginesStringOnEither) {
  const std::string model = example_path("koch/koch.l");
  const auto cpu_run = run_sylva({"run", model, "--steps", "2"});
  ASSERT_EQ(cpu_run.exit_code, 0) << cpu_run.err;
  for (const char* backend : kBackends) {
    SCOPED_TRACE(backend);
    ScopedGl gl(backend);
    const auto gpu_run = run_sylva({"run", model, "--gpu", "--steps", "2"});
    ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
    EXPECT_NE(gpu_run.err.find("deriving it on the GPU by its productions translated to GLSL"), std::string::npos)
        << gpu_run.err;
    EXPECT_EQ(gpu_run.out, cpu_run.out);
  }
}

TEST(GpuOpenGl, ABogusChoiceIsAnError) {
  ScopedGl gl("bogus");
  const std::string want = "--gpu: SYLVA_GL=bogus names no OpenGL: SYLVA_GL=egl";
  gpu::Stencil chaikin;
  chaikin.k = 2;
  chaikin.left = chaikin.right = 1;
  chaikin.c = {0.25, 0.75, 0, 0, 0.75, 0.25};
  try {
    gpu::gl_stencil_deriver().derive({0, 0, 1, 0, 1, 1}, 2, chaikin, 1);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(want, 0), 0u) << error.what();
  }
  EXPECT_THROW(gpu::gl_lsystem_deriver().scan_add({1, 2, 3}), ModelError);
  // sylva run --gpu says so and derives on the CPU.
  const auto run = run_sylva({"run", example_path("chaikin/chaikin.l"), "--gpu", "--steps", "2"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sylva: " + want), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("; deriving on the CPU"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sylva::test
