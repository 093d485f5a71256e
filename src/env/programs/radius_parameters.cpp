#include "env/programs/radius_parameters.h"

#include <cmath>

#include "env/programs/parameter_file.h"

namespace sylva::env {

RadiusParameters read_radius_parameters(const std::filesystem::path& path, const std::string& program,
                                        const std::string& example) {
  ParameterFile file(path, program, {"radius", "3d case", "verbose"}, ParameterDialect::collision);
  RadiusParameters parameters;
  const ParameterCommand& radius = file.require("radius", example);
  parameters.radius = radius.number();
  if (!(parameters.radius > 0) || !std::isfinite(parameters.radius))
    radius.fail(radius.values()[0], "expected a radius greater than 0, found '" + radius.values()[0].text + "'");
  if (const ParameterCommand* three_d = file.find("3d case")) parameters.three_d = three_d->flag();
  if (const ParameterCommand* verbose = file.find("verbose")) parameters.verbose = verbose->flag();
  return parameters;
}

}  // namespace sylva::env
