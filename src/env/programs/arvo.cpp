// arvo (EnviroManual 3.1.3): segments climbing around surfaces, after Arvo
// and Kirk's environment-sensitive automata. The surfaces are the obstacles
// of a cpfg background file and, with "add objects: on", spheres, cylinders
// and cones the model places.
//
// Parameter file (x y z may be separated by spaces, commas or 'x'):
//   domain size: x y z            the extent of the voxel grid (default: 1 1 1)
//   position: x y z               its lower front left corner (default: 0 0 0)
//   grid size: x y z              voxels along each axis (default: 1 1 1)
//   surface distance: d           required, >= 0
//   max surface distance: d       default 2 d
//   tries for Q: n                default 8
//   tries for surface: n          default 16
//   obstacles: filename           a cpfg background file (default: none)
//   add objects: on|off           default off
//   remove objects: on|off        default on
//   seed: n                       default 0
//   verbose: on|off               default off
// The grid only speeds up the ray tests; it never changes an answer.
//
// Queries, by the communication module's number of parameters (the .e file
// sends turtle position, heading and up, and the following module):
//  0     with "add objects: on", the following module S(r), C(r,h) or
//        C(r1,r2,h) becomes an obstacle: a sphere at the turtle, or a
//        cylinder or cone standing on the turtle along its heading. Objects
//        added in a pass are obstacles for the whole pass; with "remove
//        objects: on" they are removed before the next pass.
//  1..6  does the following segment (F, f, G or g with its length l) hit a
//        surface? The ray from the turtle along its heading is tested to
//        l + surface distance (the manual: the surface distance keeps an
//        object of some width away from the surface). p1 = 1 if it does,
//        else 0; with 4 or more parameters p2..p4 = the surface normal there.
//  7+    p1 = the desired segment length l. The answer is a segment of about
//        that length whose tip stays near a surface: p1..p3 = the new unit
//        heading, p4 = the segment's length (0 when none was found, heading
//        and up then unchanged), p5..p7 = the new up vector, the surface
//        normal. (The manual's table says "p3 = length", which collides with
//        the heading; the length is p4.) lpfg's EA20 has 20 parameters and is
//        answered this way.
//
// The search for a new segment (manual 3.1.3): candidate tips Q = T + l * D,
// with D in the plane perpendicular to the up vector, swept from the heading
// to +/-180 degrees: 0, +s, -s, +2s, -2s, ... with s = 360 / (tries for Q).
// From each Q rays are shot to find the closest surface within the max
// surface distance: first against the up vector (toward the surface the
// segment grew along), then in "tries for surface" - 1 random directions from
// the seeded generator. If none hits, the next Q is tried. Otherwise the new
// tip is P = hit point + normal * surface distance, accepted when the segment
// from the turtle T to P crosses no surface (the collision the program is
// there to avoid); the answer is the direction of P - T, its length and the
// normal.
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "env/programs/arvo_background_file.h"
#include "env/programs/arvo_obstacles.h"
#include "env/programs/parameter_file.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {
namespace {

// The vector operators live with the geometry (std::array has no operators to
// find by argument-dependent lookup).
using namespace arvo;

constexpr const char* kProgram = "arvo";
// Rays start this far along so that a tip lying on a surface does not hit it.
constexpr double kRayStart = 1e-6;

struct ArvoParameters {
  arvo::Domain domain;
  double surface_distance = 0;
  double max_surface_distance = -1;  // < 0: twice the surface distance
  int tries_for_q = 8;
  int tries_for_surface = 16;
  std::filesystem::path obstacles;
  bool add_objects = false;
  bool remove_objects = true;
  std::uint32_t seed = 0;
  bool verbose = false;
};

int positive_integer(const ParameterCommand& command) {
  int n = command.integer();
  if (n < 1) command.fail(command.values()[0], "expected a whole number of at least 1, found '" + command.values()[0].text + "'");
  return n;
}

ArvoParameters read_arvo_parameters(const std::filesystem::path& path) {
  ParameterFile file(path, kProgram,
                     {"domain size", "position", "grid size", "surface distance", "max surface distance", "tries for q",
                      "tries for surface", "obstacles", "add objects", "remove objects", "seed", "verbose"},
                     ParameterDialect::collision);
  ArvoParameters p;
  if (const ParameterCommand* c = file.find("domain size")) {
    auto v = c->numbers(3);
    for (int a = 0; a < 3; ++a) {
      if (!(v[a] > 0)) c->fail(c->values()[0], "expected a domain size greater than 0 along each axis");
      p.domain.size[a] = v[a];
    }
  }
  if (const ParameterCommand* c = file.find("position")) {
    auto v = c->numbers(3);
    for (int a = 0; a < 3; ++a) p.domain.position[a] = v[a];
  }
  if (const ParameterCommand* c = file.find("grid size")) {
    auto v = c->numbers(3);
    for (int a = 0; a < 3; ++a) {
      if (!(v[a] >= 1) || v[a] != std::floor(v[a]) || v[a] > 1e6f)
        c->fail(c->values()[0], "expected whole numbers of voxels, at least 1, for 'grid size:'");
      p.domain.cells[a] = static_cast<int>(v[a]);
    }
  }
  const ParameterCommand& distance = file.require("surface distance", "surface distance: 0.1");
  p.surface_distance = distance.number();
  if (!(p.surface_distance >= 0)) distance.fail(distance.values()[0], "expected a distance of at least 0");
  if (const ParameterCommand* c = file.find("max surface distance")) {
    p.max_surface_distance = c->number();
    if (!(p.max_surface_distance > 0)) c->fail(c->values()[0], "expected a distance greater than 0");
  }
  if (const ParameterCommand* c = file.find("tries for q")) p.tries_for_q = positive_integer(*c);
  if (const ParameterCommand* c = file.find("tries for surface")) p.tries_for_surface = positive_integer(*c);
  if (const ParameterCommand* c = file.find("obstacles")) p.obstacles = path.parent_path() / c->text();
  if (const ParameterCommand* c = file.find("add objects")) p.add_objects = c->flag();
  if (const ParameterCommand* c = file.find("remove objects")) p.remove_objects = c->flag();
  if (const ParameterCommand* c = file.find("seed")) p.seed = static_cast<std::uint32_t>(c->integer());
  if (const ParameterCommand* c = file.find("verbose")) p.verbose = c->flag();
  if (p.max_surface_distance < 0) p.max_surface_distance = 2 * p.surface_distance;
  return p;
}

Vec3 to_vec(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

bool is_segment(const std::string& symbol) { return symbol == "F" || symbol == "f" || symbol == "G" || symbol == "g"; }

class Arvo : public Field {
 public:
  Arvo(ProgramInvocation invocation, ArvoParameters parameters)
      : invocation_(std::move(invocation)), parameters_(std::move(parameters)), random_(parameters_.seed) {
    scene_.set_domain(parameters_.domain);
    if (!parameters_.obstacles.empty()) arvo::read_background_file(parameters_.obstacles, scene_);
    background_count_ = scene_.size();
  }

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    if (queries.empty()) return;
    const TurtleReport& first = queries[0].turtle;
    require_turtle_values(invocation_, kProgram, "turtle position", first.position_count, 3);
    require_turtle_values(invocation_, kProgram, "turtle heading", first.heading_count, 3);

    if (parameters_.remove_objects) scene_.truncate(background_count_);
    if (parameters_.add_objects)
      for (const Query& query : queries)
        if (query.module.parameters.empty()) add_object(query);

    std::size_t found = 0, asked = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      std::size_t count = queries[q].module.parameters.size();
      if (count == 0) continue;
      if (count >= 7) {
        require_turtle_values(invocation_, kProgram, "turtle up", queries[q].turtle.up_count, 3);
        ++asked;
        found += new_segment(queries[q], answers[q]);
      } else {
        segment_hit(queries[q], answers[q]);
      }
    }
    if (parameters_.verbose)
      std::cerr << kProgram << ": step " << step << ": " << queries.size() << " queries, " << scene_.size()
                << " obstacles, " << found << " of " << asked << " segments found\n";
  }

 private:
  void add_object(const Query& query) {
    const ModuleRecord& object = query.following;
    const std::vector<float>& p = object.parameters;
    arvo::Mat4 frame = arvo::frame(to_vec(query.turtle.position), to_vec(query.turtle.heading), to_vec(query.turtle.up));
    if (object.symbol == "S" && p.size() == 1) scene_.add_sphere(frame, p[0]);
    if (object.symbol == "C" && p.size() == 2) scene_.add_frustum(frame, p[0], p[0], p[1]);
    if (object.symbol == "C" && p.size() == 3) scene_.add_frustum(frame, p[0], p[1], p[2]);
  }

  void segment_hit(const Query& query, Answer& answer) const {
    const ModuleRecord& segment = query.following;
    if (!is_segment(segment.symbol) || segment.parameters.empty())
      throw std::runtime_error(std::string(kProgram) + ": a communication module with " +
                               std::to_string(query.module.parameters.size()) +
                               " parameter(s) asks whether the following segment hits a surface, so it must be "
                               "followed by F, f, G or g with its length (and the .e file must say 'following "
                               "module: yes'); found " +
                               (segment.symbol.empty() ? std::string("nothing") : "'" + segment.symbol + "'") +
                               " after module " + std::to_string(query.id));
    Vec3 heading = arvo::normalized(to_vec(query.turtle.heading));
    double reach = std::abs(segment.parameters[0]) + parameters_.surface_distance;
    auto hit = scene_.closest(to_vec(query.turtle.position), heading, kRayStart, reach);
    answer.assign(0, hit ? 1.0f : 0.0f);
    if (hit && query.module.parameters.size() >= 4)
      for (int a = 0; a < 3; ++a) answer.assign(1 + a, static_cast<float>(hit->normal[a]));
  }

  // A random direction, uniform over the sphere, from the generator's raw
  // output so that a seed gives the same directions with every library.
  Vec3 random_direction() {
    double z = 2.0 * (random_() / 4294967296.0) - 1.0;
    double angle = 2.0 * std::numbers::pi * (random_() / 4294967296.0);
    double r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::cos(angle), r * std::sin(angle), z};
  }

  struct Surface {
    Vec3 point;
    Vec3 normal;
  };

  std::optional<Surface> closest_surface(const Vec3& from, const Vec3& up) {
    std::optional<Surface> best;
    double nearest = parameters_.max_surface_distance;
    for (int ray = 0; ray < parameters_.tries_for_surface; ++ray) {
      Vec3 direction = ray == 0 && arvo::length(up) > 0 ? up * -1.0 : random_direction();
      // Unit directions: t is the distance to the surface.
      if (auto hit = scene_.closest(from, direction, 0.0, nearest)) {
        nearest = hit->t;
        best = Surface{from + direction * hit->t, hit->normal};
      }
    }
    return best;
  }

  bool new_segment(const Query& query, Answer& answer) {
    Vec3 t = to_vec(query.turtle.position);
    Vec3 heading = arvo::normalized(to_vec(query.turtle.heading));
    Vec3 up = arvo::normalized(to_vec(query.turtle.up));
    double l = query.module.parameters[0];
    // The sweep's plane: perpendicular to up, starting at the heading.
    Vec3 forward = arvo::normalized(heading - up * arvo::dot(heading, up));
    if (arvo::length(forward) == 0) forward = arvo::normalized(to_vec(query.turtle.left));
    Vec3 side = arvo::cross(up, forward);
    double step = 2 * std::numbers::pi / parameters_.tries_for_q;
    for (int k = 0; k < parameters_.tries_for_q; ++k) {
      double angle = step * ((k + 1) / 2) * (k % 2 == 1 ? 1 : -1);
      Vec3 q = t + (forward * std::cos(angle) + side * std::sin(angle)) * l;
      auto surface = closest_surface(q, up);
      if (!surface) continue;
      Vec3 p = surface->point + surface->normal * parameters_.surface_distance;
      Vec3 segment = p - t;
      double length = arvo::length(segment);
      if (length <= kRayStart) continue;
      Vec3 new_heading = segment * (1.0 / length);
      if (scene_.closest(t, new_heading, kRayStart, length)) continue;
      for (int a = 0; a < 3; ++a) {
        answer.assign(a, static_cast<float>(new_heading[a]));
        answer.assign(4 + a, static_cast<float>(surface->normal[a]));
      }
      answer.assign(3, static_cast<float>(length));
      return true;
    }
    for (int a = 0; a < 3; ++a) {
      answer.assign(a, static_cast<float>(heading[a]));
      answer.assign(4 + a, static_cast<float>(up[a]));
    }
    answer.assign(3, 0.0f);
    return false;
  }

  ProgramInvocation invocation_;
  ArvoParameters parameters_;
  arvo::ObstacleScene scene_;
  std::size_t background_count_ = 0;
  std::mt19937 random_;
};

}  // namespace

std::unique_ptr<Field> make_arvo(const ProgramInvocation& invocation) {
  std::filesystem::path path = parameter_file_path(invocation, kProgram, ParameterDialect::collision);
  return std::make_unique<Arvo>(invocation, read_arvo_parameters(path));
}

}  // namespace sylva::env
