#include "env/programs/chiba_parameters.h"

#include "env/programs/light_source_commands.h"
#include "env/programs/parameter_file.h"

namespace sylva::env {

ChibaParameters read_chiba_parameters(const std::filesystem::path& path) {
  ParameterFile file(path, "chiba",
                     {"grid size", "number of samples", "lower to upper ratio", "use CIE formula", "source direction",
                      "transmittance", "radius", "beam radius", "estimate intersection area", "verbose"},
                     ParameterDialect::light);
  ChibaParameters p;
  light::SourceLines sources;
  for (const ParameterCommand& line : file.commands()) {
    const std::string& k = line.name();
    if (k == "grid size") {
      p.grid_size = light::read_grid_size(line);
    } else if (k == "number of samples") {
      p.samples = line.read_positive_integers(1, "the number of samples of the light sphere")[0];
    } else if (k == "lower to upper ratio") {
      p.lower_to_upper = line.read_number_in(0, 1, "the ratio of lower to upper hemisphere intensity");
    } else if (k == "use cie formula") {
      p.cie_overcast = line.read_flag();
    } else if (k == "source direction") {
      sources.read(line);
    } else if (k == "transmittance") {
      p.transmittance = line.read_number_in(0, 1, "the transmittance");
    } else if (k == "radius") {
      p.radius = line.read_number_at_least(0, "the default sphere radius");
    } else if (k == "beam radius") {
      p.beam_radius = line.read_number_in(0, 1, "the beam radius (a fraction of the sphere's radius)");
    } else if (k == "estimate intersection area") {
      p.estimate_intersection_area = line.read_flag();
    } else if (k == "verbose") {
      p.verbose = line.read_flag();
    } else {
      file.fail_unknown(line);
    }
  }
  if (!sources.empty()) p.sources = sources.normalized();
  return p;
}

}  // namespace sylva::env
