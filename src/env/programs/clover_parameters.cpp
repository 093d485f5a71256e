#include "env/programs/clover_parameters.h"

#include <stdexcept>

#include "env/programs/light_parameter_file.h"

namespace sylva::env {

using namespace light;

CloverParameters read_clover_parameters(const std::filesystem::path& path) {
  const std::vector<std::string> known{"grid range",        "grid position", "grid size", "transmittance",
                                       "input image",       "remove old leaves", "z is up", "verbose"};
  CloverParameters p;
  bool has_range = false, has_size = false, has_transmittance = false;
  for (const ParameterLine& line : read_parameter_file(path, "clover")) {
    const std::string& k = line.keyword;
    if (k == "grid range") {
      std::vector<double> v = read_numbers(line, 2, "the grid's width and depth in world units");
      if (!(v[0] > 0 && v[1] > 0)) fail_at(line, first_value_column(line), "expected a grid range greater than 0");
      p.range = {v[0], v[1]};
      has_range = true;
    } else if (k == "grid position") {
      std::vector<double> v = read_numbers(line, 2, "the grid's lower left corner x y");
      p.position = {v[0], v[1]};
    } else if (k == "grid size") {
      std::vector<int> n = read_positive_integers(line, 2, "voxels along the two ground axes");
      if (static_cast<double>(n[0]) * n[1] > 1e9) fail_at(line, first_value_column(line), "the grid has too many voxels");
      p.size = {n[0], n[1]};
      has_size = true;
    } else if (k == "transmittance") {
      p.transmittance = read_number_in(line, 0, 1, "the transmittance of leaves");
      has_transmittance = true;
    } else if (k == "input image") {
      std::filesystem::path image = read_word(line, "an image file name");
      if (image.is_relative()) image = path.parent_path() / image;
      try {
        p.image = read_green_channel(image);
      } catch (const std::exception& error) {
        fail_at(line, first_value_column(line), "input image " + image.string() + ": " + error.what());
      }
    } else if (k == "remove old leaves") {
      p.remove_old_leaves = read_flag(line);
    } else if (k == "z is up") {
      p.z_is_up = read_flag(line);
    } else if (k == "verbose") {
      p.verbose = read_flag(line);
    } else {
      fail_unknown_keyword(line, known);
    }
  }
  if (!has_range) fail_missing(path, "clover", "grid range: x y");
  if (!has_size) fail_missing(path, "clover", "grid size: x y");
  if (!has_transmittance) fail_missing(path, "clover", "transmittance: t");
  return p;
}

}  // namespace sylva::env
