// ecosystem (EnviroManual 3.1.2): collisions between objects of different
// sizes, disks in 2D or spheres with "3d case: on", e.g. plants in a field.
//
// Parameter file:   grid size: x y [z]  (required; voxels per axis, z for 3D)
//                   vigor: on|off       (default off)
//                   3d case: on|off     (default off)
//                   verbose: on|off     (default off)
// Query:  ?E(radius), or ?E(radius, vigor) with "vigor: on", at the turtle
//         position.
// Answer: p1 = 0 if the object collides with an object that beats it, 1
//         otherwise; p2 unchanged. Modules without parameters take no part.
//
// Two objects collide when they overlap: their centres are closer than the
// sum of their radii (touching is no collision; one inside the other is a
// collision). Without vigor the object loses when its radius is less than or
// equal to the other's, so two equal colliding objects both answer 0. With
// vigor it loses to a higher vigor and, at equal vigor, to a radius at least
// as large.
//
// As in the manual, the objects are entered into every voxel of a grid fitted
// tightly around them that their bounding box touches, and each object is
// tested against the objects sharing its voxels. Overlapping objects always
// share a voxel, so the grid decides only the speed, never the answer; the
// given grid size is the least resolution, refined when the objects are many.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "env/programs/grid_uniform.h"
#include "env/programs/parameter_file.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {
namespace {

using collision::Point3;
using collision::UniformGrid;

constexpr const char* kProgram = "ecosystem";

struct EcosystemParameters {
  std::array<int, 3> grid_size{1, 1, 1};
  bool vigor = false;
  bool three_d = false;
  bool verbose = false;
};

EcosystemParameters read_ecosystem_parameters(const std::filesystem::path& path) {
  ParameterFile file(path, kProgram, {"grid size", "vigor", "3d case", "verbose"}, ParameterDialect::collision);
  EcosystemParameters parameters;
  const ParameterCommand& grid = file.require("grid size", "grid size: 20 20");
  std::vector<float> size = grid.numbers(3, /*optional_last=*/true, /*fallback=*/1);
  for (int a = 0; a < 3; ++a) {
    if (!(size[a] >= 1) || size[a] != std::floor(size[a]) || size[a] > 1e6f)
      grid.fail(grid.values().empty() ? ParameterWord{} : grid.values()[0],
                "expected whole numbers of voxels, at least 1, for 'grid size:'");
    parameters.grid_size[a] = static_cast<int>(size[a]);
  }
  if (const ParameterCommand* vigor = file.find("vigor")) parameters.vigor = vigor->flag();
  if (const ParameterCommand* three_d = file.find("3d case")) parameters.three_d = three_d->flag();
  if (const ParameterCommand* verbose = file.find("verbose")) parameters.verbose = verbose->flag();
  return parameters;
}

class Ecosystem : public Field {
 public:
  Ecosystem(ProgramInvocation invocation, EcosystemParameters parameters)
      : invocation_(std::move(invocation)), parameters_(parameters) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<std::size_t> query_of = queries_with_parameters(queries);
    if (query_of.empty()) return;
    require_turtle_position(invocation_, kProgram, queries[query_of[0]], parameters_.three_d);

    std::size_t count = query_of.size();
    std::vector<Point3> centres(count);
    std::vector<float> radius(count), vigor(count, 0.0f);
    double diameters = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const Query& query = queries[query_of[i]];
      if (parameters_.vigor && query.module.parameters.size() < 2)
        throw std::runtime_error(std::string(kProgram) + ": with 'vigor: on' every communication module needs two " +
                                 "parameters (radius, vigor); module " + query.module.symbol + " at position " +
                                 std::to_string(query.id) + " has one");
      centres[i] = position_in(query, parameters_.three_d);
      // A negative radius is no object at all; it still gets an answer.
      radius[i] = std::max(query.module.parameters[0], 0.0f);
      if (parameters_.vigor) vigor[i] = query.module.parameters[1];
      diameters += 2.0 * radius[i];
    }
    std::array<int, 3> least = parameters_.grid_size;
    if (!parameters_.three_d) least[2] = 1;
    UniformGrid grid(centres, radius, parameters_.three_d ? 3 : 2, static_cast<float>(diameters / count), least);

    std::size_t colliding = 0;
    for (std::size_t i = 0; i < count; ++i) {
      bool beaten = grid.visit_near(centres[i], radius[i], [&](std::size_t j) {
        if (j == i || !beats(j, i, radius, vigor)) return false;
        double dx = centres[j][0] - centres[i][0], dy = centres[j][1] - centres[i][1],
               dz = centres[j][2] - centres[i][2];
        double reach = static_cast<double>(radius[i]) + radius[j];
        return dx * dx + dy * dy + dz * dz < reach * reach;
      });
      answers[query_of[i]].assign(0, beaten ? 0.0f : 1.0f);
      colliding += beaten;
    }
    if (parameters_.verbose)
      std::cerr << kProgram << ": step " << step << ": " << count << " objects, " << colliding << " colliding\n";
  }

 private:
  // Whether object j, if it overlaps object i, makes i answer 0.
  bool beats(std::size_t j, std::size_t i, const std::vector<float>& radius, const std::vector<float>& vigor) const {
    if (parameters_.vigor && vigor[i] != vigor[j]) return vigor[i] < vigor[j];
    return radius[i] <= radius[j];
  }

  ProgramInvocation invocation_;
  EcosystemParameters parameters_;
};

}  // namespace

std::unique_ptr<Field> make_ecosystem(const ProgramInvocation& invocation) {
  std::filesystem::path path = parameter_file_path(invocation, kProgram, ParameterDialect::collision);
  return std::make_unique<Ecosystem>(invocation, read_ecosystem_parameters(path));
}

}  // namespace sylva::env
