// `sylva run MODEL --gpu`: a point-subdivision L-system (gpu/stencil_probe.h)
// derived on the GPU (gpu/stencil_deriver.h), or else an L-system whose
// productions translate to GLSL (gpu/lsystem_glsl.h: successors of varying
// length placed by a scan-add), its final string written as the CPU path
// writes it.
#pragma once

#include <string>

#include "api/simulation.h"

namespace sylva::gpu {

// Probes the model for a stencil, then tries to translate its productions;
// if either succeeds, derives `steps` steps (the model's derivation length
// if negative) on the GPU, writes the string to `string_path` ("-":
// standard output) and returns true. Otherwise tells why on standard error
// ("sylva: --gpu: MODEL is not a point-subdivision L-system: REASON; nor an
// L-system whose productions translate to GLSL: REASON; deriving on the
// CPU") and returns false.
bool run_on_gpu(const std::string& model, const SimulationOptions& options, int steps,
                const std::string& string_path);

}  // namespace sylva::gpu
