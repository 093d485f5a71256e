#include "env/programs/takenaka_parameters.h"

#include "env/programs/light_parameter_file.h"

namespace sylva::env {

using namespace light;

TakenakaParameters read_takenaka_parameters(const std::filesystem::path& path) {
  const std::vector<std::string> known{"grid size", "parameter",   "transmittance", "efficiency",
                                       "source",    "beam radius", "verbose"};
  TakenakaParameters p;
  const ParameterLine* first_source = nullptr;
  std::vector<ParameterLine> lines = read_parameter_file(path, "takenaka");
  for (const ParameterLine& line : lines) {
    const std::string& k = line.keyword;
    if (k == "grid size") {
      std::vector<int> n = read_positive_integers(line, 3, "voxels along x, y and z");
      p.grid_size = {n[0], n[1], n[2]};
    } else if (k == "parameter") {
      p.sparsity = read_number_at_least(line, 1, "the sparsity of matter in a sphere");
    } else if (k == "transmittance") {
      p.transmittance = read_number_in(line, 0, 1, "the transmittance");
    } else if (k == "efficiency") {
      p.efficiency = read_number(line, "the efficiency");
    } else if (k == "source") {
      std::vector<double> v = read_numbers(line, 4, "direction x y z and intensity");
      if (v[0] == 0 && v[1] == 0 && v[2] == 0) fail_at(line, first_value_column(line), "expected a direction other than 0 0 0");
      if (v[3] < 0) fail_at(line, first_value_column(line), "expected an intensity of 0 or more");
      p.sources.push_back({{v[0], v[1], v[2]}, v[3]});
      if (!first_source) first_source = &line;
    } else if (k == "beam radius") {
      p.beam_radius = read_number_in(line, 0, 1, "the beam radius (a fraction of the sphere's radius)");
    } else if (k == "verbose") {
      p.verbose = read_flag(line);
    } else {
      fail_unknown_keyword(line, known);
    }
  }
  if (p.sources.empty()) fail_missing(path, "takenaka", "source: x y z intensity");
  double total = 0;
  for (const light::LightSource& s : p.sources) total += s.intensity;
  if (!(total > 0)) fail_at(*first_source, first_value_column(*first_source), "the sources' intensities add up to 0");
  light::normalize_sources(p.sources);
  return p;
}

}  // namespace sylva::env
