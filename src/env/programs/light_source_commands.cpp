#include "env/programs/light_source_commands.h"

namespace sylva::env::light {

std::array<int, 3> read_grid_size(const ParameterCommand& command) {
  std::vector<int> n = command.read_positive_integers(3, "voxels along x, y and z");
  return {n[0], n[1], n[2]};
}

void SourceLines::read(const ParameterCommand& command) {
  std::vector<double> v = command.read_numbers(4, "direction x y z and intensity");
  if (v[0] == 0 && v[1] == 0 && v[2] == 0)
    command.fail(command.first_value_column(), "expected a direction other than 0 0 0");
  if (v[3] < 0) command.fail(command.first_value_column(), "expected an intensity of 0 or more");
  sources_.push_back({{v[0], v[1], v[2]}, v[3]});
  if (!first_) first_ = &command;
}

std::vector<LightSource> SourceLines::normalized() const {
  double total = 0;
  for (const LightSource& s : sources_) total += s.intensity;
  if (!(total > 0)) first_->fail(first_->first_value_column(), "the sources' intensities add up to 0");
  std::vector<LightSource> sources = sources_;
  normalize_sources(sources);
  return sources;
}

}  // namespace sylva::env::light
