#include "gpu/gpu_run.h"

#include <cstdio>

#include "gpu/stencil_probe.h"
#include "io/output_file.h"

namespace sylva::gpu {

bool run_on_gpu(const std::string& model, const SimulationOptions& options, int steps,
                const std::string& string_path) {
  ProbeResult probe;
  int length = steps;
  {
    Simulation simulation(model, options);
    probe = probe_stencil(simulation);
    if (length < 0) length = simulation.derivation_length();
  }
  if (!probe.in_class) {
    std::fprintf(stderr, "sylva: --gpu: %s is not a point-subdivision L-system: %s; deriving on the CPU\n",
                 model.c_str(), probe.reason.c_str());
    return false;
  }
  std::vector<double> points;
  try {
    points = gl_stencil_deriver().derive(probe.axiom.points, probe.axiom.dim, probe.stencil, length);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sylva: %s; deriving on the CPU\n", error.what());
    return false;
  }
  io::write_output_file(string_path, format_point_string(probe.axiom, points, true) + "\n");
  return true;
}

}  // namespace sylva::gpu
