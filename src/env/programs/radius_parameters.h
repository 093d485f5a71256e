// The parameter file of honda81 and density: one radius, 2D or 3D.
//
//   radius: r        (required, > 0)
//   3d case: on|off  (default off)
//   verbose: on|off  (default off)
#pragma once

#include <filesystem>
#include <string>

namespace sylva::env {

struct RadiusParameters {
  float radius = 0;
  bool three_d = false;
  bool verbose = false;
};

// `program` names the program in messages; `example` is the radius line a
// message for a missing one suggests.
RadiusParameters read_radius_parameters(const std::filesystem::path& path, const std::string& program,
                                        const std::string& example);

}  // namespace sylva::env
