// density: how crowded the neighbourhood of each communication module is.
//
// The Virtual Laboratory's manuals do not describe a program of this name;
// this definition is Sylva's own.
//
// Parameter file:   radius: r       (required, > 0) the neighbourhood's radius
//                   3d case: on|off (default off)
//                   verbose: on|off (default off)
// Query:  ?E(n) or ?E(n, d) at the turtle position (x y, or x y z in 3D);
//         the parameters are ignored on input.
// Answer: p1 = the number of other communication modules of the same pass
//         whose positions are closer than r (points at distance exactly r
//         are not counted);
//         p2 = that number per unit area, p1 / (pi r^2), or in 3D per unit
//         volume, p1 / (4/3 pi r^3).
// Modules without parameters are counted as neighbours but get no answer.
#include <cmath>
#include <iostream>
#include <numbers>

#include "env/programs/grid_uniform.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"
#include "env/programs/radius_parameters.h"

namespace sylva::env {
namespace {

using collision::Point3;
using collision::UniformGrid;

constexpr const char* kProgram = "density";

class Density : public Field {
 public:
  Density(ProgramInvocation invocation, RadiusParameters parameters)
      : invocation_(std::move(invocation)), parameters_(parameters) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    if (queries.empty()) return;
    require_turtle_position(invocation_, kProgram, queries[0], parameters_.three_d);
    std::size_t count = queries.size();
    std::vector<Point3> centres(count);
    for (std::size_t i = 0; i < count; ++i) centres[i] = position_in(queries[i], parameters_.three_d);
    std::vector<float> points(count, 0.0f);
    float r = parameters_.radius;
    UniformGrid grid(centres, points, parameters_.three_d ? 3 : 2, r);

    double measure = parameters_.three_d ? 4.0 / 3.0 * std::numbers::pi * r * r * r : std::numbers::pi * r * r;
    double r_squared = static_cast<double>(r) * r;
    for (std::size_t i = 0; i < count; ++i) {
      const std::vector<float>& p = queries[i].module.parameters;
      if (p.empty()) continue;
      std::size_t neighbours = 0;
      grid.visit_near(centres[i], r, [&](std::size_t j) {
        double dx = centres[j][0] - centres[i][0], dy = centres[j][1] - centres[i][1],
               dz = centres[j][2] - centres[i][2];
        if (j != i && dx * dx + dy * dy + dz * dz < r_squared) ++neighbours;
        return false;
      });
      answers[i].assign(0, static_cast<float>(neighbours));
      if (p.size() > 1) answers[i].assign(1, static_cast<float>(neighbours / measure));
    }
    if (parameters_.verbose) std::cerr << kProgram << ": step " << step << ": " << count << " points\n";
  }

 private:
  ProgramInvocation invocation_;
  RadiusParameters parameters_;
};

}  // namespace

std::unique_ptr<Field> make_density(const ProgramInvocation& invocation) {
  std::filesystem::path path = parameter_file_path(invocation, kProgram, ParameterDialect::collision);
  return std::make_unique<Density>(invocation, read_radius_parameters(path, kProgram, "radius: 2"));
}

}  // namespace sylva::env
