#include "env/programs/takenaka_parameters.h"

#include "env/programs/light_source_commands.h"
#include "env/programs/parameter_file.h"

namespace sylva::env {

TakenakaParameters read_takenaka_parameters(const std::filesystem::path& path) {
  ParameterFile file(path, "takenaka",
                     {"grid size", "parameter", "transmittance", "efficiency", "source", "beam radius", "verbose"},
                     ParameterDialect::light);
  TakenakaParameters p;
  light::SourceLines sources;
  for (const ParameterCommand& line : file.commands()) {
    const std::string& k = line.name();
    if (k == "grid size") {
      p.grid_size = light::read_grid_size(line);
    } else if (k == "parameter") {
      p.sparsity = line.read_number_at_least(1, "the sparsity of matter in a sphere");
    } else if (k == "transmittance") {
      p.transmittance = line.read_number_in(0, 1, "the transmittance");
    } else if (k == "efficiency") {
      p.efficiency = line.read_number("the efficiency");
    } else if (k == "source") {
      sources.read(line);
    } else if (k == "beam radius") {
      p.beam_radius = line.read_number_in(0, 1, "the beam radius (a fraction of the sphere's radius)");
    } else if (k == "verbose") {
      p.verbose = line.read_flag();
    } else {
      file.fail_unknown(line);
    }
  }
  if (sources.empty()) file.fail_missing("source", "source: x y z intensity");
  p.sources = sources.normalized();
  return p;
}

}  // namespace sylva::env
