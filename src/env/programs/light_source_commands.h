// The commands chiba and takenaka parameter files have in common: the
// voxel grid and explicit light sources (EnviroManual 3.2.2, 3.2.3).
#pragma once

#include <array>
#include <vector>

#include "env/programs/light_sources.h"
#include "env/programs/parameter_file.h"

namespace sylva::env::light {

// "grid size: x y z", voxels along each axis.
std::array<int, 3> read_grid_size(const ParameterCommand& command);

// The sources of the file's "source direction:" (chiba) or "source:"
// (takenaka) lines, "x y z intensity" each, in file order.
class SourceLines {
 public:
  void read(const ParameterCommand& command);
  bool empty() const { return sources_.empty(); }
  // The sources normalized (light_sources.h); an error at the first source
  // line when their intensities add up to 0. Call only when not empty().
  std::vector<LightSource> normalized() const;

 private:
  std::vector<LightSource> sources_;
  const ParameterCommand* first_ = nullptr;
};

}  // namespace sylva::env::light
