// The takenaka parameter file (EnviroManual 3.2.3).
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "env/programs/light_sources.h"

namespace sylva::env {

struct TakenakaParameters {
  // The manual's voxel grid for ray casting; checked, but the answers do not
  // depend on it (see takenaka.cpp). The paper used 32 x 32 x 32.
  std::array<int, 3> grid_size{32, 32, 32};
  double sparsity = 1.5;  // "parameter:": sphere radius over the radius of its matter alone
  double transmittance = 0.1;
  double efficiency = 0.015;
  std::vector<light::LightSource> sources;  // normalized; at least one
  double beam_radius = 0;                   // a fraction of the shooting sphere's radius
  bool verbose = false;
};

// Throws ModelError with the file, line and column of what is wrong.
TakenakaParameters read_takenaka_parameters(const std::filesystem::path& path);

}  // namespace sylva::env
