// honda81 (EnviroManual 3.1.1): collisions between disks of one fixed radius
// that differ only in vigor, in 2D or, with "3d case: on", between spheres.
//
// Parameter file:   radius: r      (required, > 0)
//                   3d case: on|off (default off)
//                   verbose: on|off (default off)
// Query:  ?E(vigor) or ?E(vigor, group), at the turtle position (x y, or
//         x y z in 3D); the group defaults to 0.
// Answer: p1 = 0 if the disk collides with a disk of the same group with a
//         higher vigor, 1 otherwise; p2 unchanged. Modules without
//         parameters take no part.
//
// Every query of a pass is stored, then each object is compared with the
// other objects of its group (manual: "the distance from a given object to
// other objects having a higher or equal vigor"). Two disks of radius r
// collide when their centres are closer than 2r (touching is no collision).
// Equal vigor answers 1 for both ("1 (equal or higher vigor)"), so an object
// of vigor 1, the highest, is never stopped and stops every weaker object it
// touches. Objects are compared within one pass only: a model keeps an object
// in the environment by keeping its communication module in the string.
#include <cmath>
#include <iostream>

#include "env/programs/grid_uniform.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"
#include "env/programs/radius_parameters.h"

namespace sylva::env {
namespace {

using collision::Point3;
using collision::UniformGrid;

constexpr const char* kProgram = "honda81";

class Honda81 : public Field {
 public:
  Honda81(ProgramInvocation invocation, RadiusParameters parameters)
      : invocation_(std::move(invocation)), parameters_(parameters) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    // The objects: queries with at least the vigor parameter.
    std::vector<std::size_t> query_of = queries_with_parameters(queries);
    if (query_of.empty()) return;
    require_turtle_position(invocation_, kProgram, queries[query_of[0]], parameters_.three_d);

    std::size_t count = query_of.size();
    std::vector<Point3> centres(count);
    std::vector<float> vigor(count), group(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Query& query = queries[query_of[i]];
      centres[i] = position_in(query, parameters_.three_d);
      vigor[i] = query.module.parameters[0];
      group[i] = query.module.parameters.size() > 1 ? query.module.parameters[1] : 0.0f;
    }
    std::vector<float> points(count, 0.0f);  // the grid holds centres only
    float reach = 2 * parameters_.radius;
    UniformGrid grid(centres, points, parameters_.three_d ? 3 : 2, reach);

    float reach_squared = reach * reach;
    std::size_t stopped = 0;
    for (std::size_t i = 0; i < count; ++i) {
      bool beaten = grid.visit_near(centres[i], reach, [&](std::size_t j) {
        if (vigor[j] <= vigor[i] || group[j] != group[i]) return false;
        float dx = centres[j][0] - centres[i][0], dy = centres[j][1] - centres[i][1], dz = centres[j][2] - centres[i][2];
        return dx * dx + dy * dy + dz * dz < reach_squared;
      });
      answers[query_of[i]].assign(0, beaten ? 0.0f : 1.0f);
      stopped += beaten;
    }
    if (parameters_.verbose)
      std::cerr << kProgram << ": step " << step << ": " << count << " objects, " << stopped << " stopped\n";
  }

 private:
  ProgramInvocation invocation_;
  RadiusParameters parameters_;
};

}  // namespace

std::unique_ptr<Field> make_honda81(const ProgramInvocation& invocation) {
  std::filesystem::path path = parameter_file_path(invocation, kProgram, ParameterDialect::collision);
  return std::make_unique<Honda81>(invocation, read_radius_parameters(path, kProgram, "radius: 0.5"));
}

}  // namespace sylva::env
