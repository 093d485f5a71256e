#include "gpu/gpu_run.h"

#include <cstdio>

#include "gpu/lsystem_glsl.h"
#include "gpu/stencil_probe.h"
#include "io/output_file.h"

namespace sylva::gpu {

// ---- algorithm 2 (gpu/lsystem_glsl.h): the productions translated to GLSL,
// successors of different lengths placed by a scan-add.
namespace {

bool run_translated_on_gpu(const std::string& model, const SimulationOptions& options, int length,
                           const std::string& string_path, const std::string& probe_reason) {
  LsystemTranslation translation;
  try {
    Simulation simulation(model, options);
    translation = translate_lsystem(simulation, options.build);
  } catch (const std::exception& error) {
    translation.in_class = false;
    translation.reason = error.what();
  }
  if (!translation.in_class) {
    std::fprintf(stderr,
                 "sylva: --gpu: %s is not a point-subdivision L-system: %s; nor an L-system whose productions "
                 "translate to GLSL: %s; deriving on the CPU\n",
                 model.c_str(), probe_reason.c_str(), translation.reason.c_str());
    return false;
  }
  GpuString derived;
  try {
    derived = gl_lsystem_deriver().derive(translation.program, translation.axiom, length);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sylva: %s; deriving on the CPU\n", error.what());
    return false;
  }
  std::fprintf(stderr,
               "sylva: --gpu: %s is not a point-subdivision L-system: %s; deriving it on the GPU by its productions "
               "translated to GLSL (algorithm 2), through %s\n",
               model.c_str(), probe_reason.c_str(), gl_lsystem_deriver().name().c_str());
  io::write_output_file(string_path, format_gpu_string(translation.program, derived, true) + "\n");
  return true;
}

}  // namespace

bool run_on_gpu(const std::string& model, const SimulationOptions& options, int steps,
                const std::string& string_path) {
  ProbeResult probe;
  int length = steps;
  {
    Simulation simulation(model, options);
    probe = probe_stencil(simulation);
    if (length < 0) length = simulation.derivation_length();
  }
  if (!probe.in_class) return run_translated_on_gpu(model, options, length, string_path, probe.reason);
  std::vector<double> points;
  try {
    points = gl_stencil_deriver().derive(probe.axiom.points, probe.axiom.dim, probe.stencil, length);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sylva: %s; deriving on the CPU\n", error.what());
    return false;
  }
  if (options.build.verbose)
    std::fprintf(stderr, "sylva: --gpu: %s derived by its stencil (algorithm 1) through %s\n", model.c_str(),
                 gl_stencil_deriver().name().c_str());
  io::write_output_file(string_path, format_point_string(probe.axiom, points, true) + "\n");
  return true;
}

}  // namespace sylva::gpu
