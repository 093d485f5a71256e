// honda81 (EnviroManual 3.1.1; the Virtual Laboratory's ENVIRO/honda81):
// collisions between the ends of segments, each with a vigor, in 2D or 3D.
//
// Specification file (read as honda81 reads it, vlab_spec_file.h):
//   radius: r        the distance within which two objects collide (default 0)
//   3d case: on      compare x y z; otherwise x and z (the default)
//   verbose: on
// Query:  ?E(vigor) or ?E(vigor, group) (E1, E2, EA20 in lpfg) at the turtle
//         position, which the .e file must send with three values.
// Answer: p1 = 0 when another object of the same group whose vigor is equal
//         or higher lies at a distance of r or less, 1 otherwise. Only p1 is
//         answered (so lpfg, which wants two values for an E2, drops it).
//
// The rule is the real program's, which the manual words loosely:
//  - Distances are compared with <=, squared, in float: touching collides.
//  - Equal vigor collides: two objects at one place stop each other, and a
//    set of objects of one vigor all stop where they crowd.
//  - The group is the second parameter truncated to an integer.
//  - In 2D the program compares x and z, not x and y: the real program reads
//    the position's third value as its second coordinate.
//  - A query without parameters, or without three position values, gets no
//    answer and takes no part (the real program says so and skips it).
// Objects are compared within one pass only.
#include <cmath>
#include <iostream>

#include "env/programs/grid_uniform.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"
#include "env/programs/vlab_spec_file.h"

namespace sylva::env {
namespace {

using collision::Point3;
using collision::UniformGrid;

constexpr const char* kProgram = "honda81";
constexpr const char* kValueDelimiters = "x,; \t:\n";

struct Honda81Settings {
  float radius = 0;
  bool three_d = false;
  bool verbose = false;
};

Honda81Settings read_honda81_settings(const std::filesystem::path& path) {
  Honda81Settings settings;
  read_vlab_spec_file(path, kProgram, {"verbose", "radius", "3d case"}, [&](std::size_t keyword, SpecLineTokens& line) {
    switch (keyword) {
      case 0: line.next_switch(kValueDelimiters, {"on"}, {"off"}, true, settings.verbose); break;
      case 1:
        if (std::optional<double> radius = line.next_number(kValueDelimiters)) settings.radius = static_cast<float>(*radius);
        break;
      case 2: line.next_switch(kValueDelimiters, {"on"}, {"off"}, true, settings.three_d); break;
    }
  });
  return settings;
}

class Honda81 : public Field {
 public:
  explicit Honda81(Honda81Settings settings) : settings_(settings) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<std::size_t> query_of;
    std::size_t without_parameters = 0, without_position = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      if (queries[q].turtle.position_count < 3) ++without_position;
      else if (queries[q].module.parameters.empty()) ++without_parameters;
      else query_of.push_back(q);
    }
    if (without_position > 0)
      warn_once(warned_position_, std::to_string(without_position) +
                                      " communication modules skipped: the .e file does not send the turtle "
                                      "position with three values ('turtle position: %f %f %f')");
    if (without_parameters > 0)
      warn_once(warned_parameters_, std::to_string(without_parameters) +
                                        " communication modules without parameters skipped (the vigor is the first)");
    if (query_of.empty()) return;

    const std::size_t count = query_of.size();
    std::vector<Point3> centres(count);
    std::vector<float> vigor(count);
    std::vector<int> group(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Query& query = queries[query_of[i]];
      const std::array<float, 3>& p = query.turtle.position;
      centres[i] = settings_.three_d ? Point3{p[0], p[1], p[2]} : Point3{p[0], p[2], 0.0f};
      vigor[i] = query.module.parameters[0];
      group[i] = query.module.parameters.size() > 1 ? static_cast<int>(query.module.parameters[1]) : 0;
    }
    const float radius = std::fabs(settings_.radius);
    const float radius_squared = settings_.radius * settings_.radius;
    std::vector<float> no_radii(count, 0.0f);  // the grid holds centres only
    UniformGrid grid(centres, no_radii, settings_.three_d ? 3 : 2, radius);
    // The grid only narrows the search; a margin keeps a neighbour at exactly
    // the radius inside the cells visited despite rounding.
    const float reach = radius * 1.001f + 1e-6f;

    std::size_t stopped = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const bool beaten = grid.visit_near(centres[i], reach, [&](std::size_t j) {
        if (j == i || group[j] != group[i] || vigor[i] > vigor[j]) return false;
        const float dx = centres[i][0] - centres[j][0], dy = centres[i][1] - centres[j][1];
        float distance_squared = dx * dx + dy * dy;
        if (settings_.three_d) {
          const float dz = centres[i][2] - centres[j][2];
          distance_squared += dz * dz;
        }
        return distance_squared <= radius_squared;
      });
      answers[query_of[i]].assign(0, beaten ? 0.0f : 1.0f);
      stopped += beaten;
    }
    if (settings_.verbose)
      std::cerr << kProgram << ": pass before step " << step + 1 << ": " << count << " objects, " << stopped
                << " stopped\n";
  }

 private:
  static void warn_once(bool& warned, const std::string& message) {
    if (warned) return;
    warned = true;
    std::cerr << "warning: " << kProgram << ": " << message << "\n";
  }

  Honda81Settings settings_;
  bool warned_position_ = false;
  bool warned_parameters_ = false;
};

}  // namespace

std::unique_ptr<Field> make_honda81(const ProgramInvocation& invocation) {
  return std::make_unique<Honda81>(read_honda81_settings(vlab_spec_file_path(invocation, kProgram)));
}

}  // namespace sylva::env
