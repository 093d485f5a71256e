// The chiba parameter file (EnviroManual 3.2.2).
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "env/programs/light_sources.h"

namespace sylva::env {

struct ChibaParameters {
  // The manual's voxel grid for ray casting; checked, but the answers do not
  // depend on it (see chiba.cpp).
  std::array<int, 3> grid_size{64, 64, 64};
  int samples = 128;
  double lower_to_upper = 0.7;
  bool cie_overcast = false;
  // "source direction:" lines, normalized; when present they replace the
  // sampled light sphere.
  std::vector<light::LightSource> sources;
  double transmittance = 0.6;
  double radius = 25;
  double beam_radius = 0;  // a fraction of the shooting sphere's radius
  bool estimate_intersection_area = false;
  bool verbose = false;
};

// Throws ModelError with the file, line and column of what is wrong.
ChibaParameters read_chiba_parameters(const std::filesystem::path& path);

}  // namespace sylva::env
