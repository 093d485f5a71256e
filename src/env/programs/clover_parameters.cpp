#include "env/programs/clover_parameters.h"

#include <stdexcept>

#include "env/programs/parameter_file.h"

namespace sylva::env {

CloverParameters read_clover_parameters(const std::filesystem::path& path) {
  ParameterFile file(path, "clover",
                     {"grid range", "grid position", "grid size", "transmittance", "input image", "remove old leaves",
                      "z is up", "verbose"},
                     ParameterDialect::light);
  CloverParameters p;
  bool has_range = false, has_size = false, has_transmittance = false;
  for (const ParameterCommand& line : file.commands()) {
    const std::string& k = line.name();
    if (k == "grid range") {
      std::vector<double> v = line.read_numbers(2, "the grid's width and depth in world units");
      if (!(v[0] > 0 && v[1] > 0)) line.fail(line.first_value_column(), "expected a grid range greater than 0");
      p.range = {v[0], v[1]};
      has_range = true;
    } else if (k == "grid position") {
      std::vector<double> v = line.read_numbers(2, "the grid's lower left corner x y");
      p.position = {v[0], v[1]};
    } else if (k == "grid size") {
      std::vector<int> n = line.read_positive_integers(2, "voxels along the two ground axes");
      if (static_cast<double>(n[0]) * n[1] > 1e9) line.fail(line.first_value_column(), "the grid has too many voxels");
      p.size = {n[0], n[1]};
      has_size = true;
    } else if (k == "transmittance") {
      p.transmittance = line.read_number_in(0, 1, "the transmittance of leaves");
      has_transmittance = true;
    } else if (k == "input image") {
      std::filesystem::path image = line.read_word("an image file name");
      if (image.is_relative()) image = path.parent_path() / image;
      try {
        p.image = read_green_channel(image);
      } catch (const std::exception& error) {
        line.fail(line.first_value_column(), "input image " + image.string() + ": " + error.what());
      }
    } else if (k == "remove old leaves") {
      p.remove_old_leaves = line.read_flag();
    } else if (k == "z is up") {
      p.z_is_up = line.read_flag();
    } else if (k == "verbose") {
      p.verbose = line.read_flag();
    } else {
      file.fail_unknown(line);
    }
  }
  if (!has_range) file.fail_missing("grid range", "grid range: x y");
  if (!has_size) file.fail_missing("grid size", "grid size: x y");
  if (!has_transmittance) file.fail_missing("transmittance", "transmittance: t");
  return p;
}

}  // namespace sylva::env
