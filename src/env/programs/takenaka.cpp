// takenaka: direct light reaching leaf clusters, less their maintenance cost
// (EnviroManual 3.2.3, after Takenaka 1994, as used in Mech & Prusinkiewicz,
// "Visual models of plants interacting with their environment", 1996).
//
// Every query is a cluster at the turtle position: p1 = its area A (of the
// matter in it), p2 = its maintenance cost c. The matter alone would fill a
// sphere of radius r = sqrt(A / pi); the sparse cluster is a sphere of radius
// R = s * r (s = "parameter:"). From the centre of each cluster a beam is cast
// towards every source: a disk of radius b * R (b = "beam radius:") across the
// direction of the light. Every other cluster ahead of it whose projected disk
// (radius R_j) covers a part f of the beam's disk lets through
// (1 - f) + f * t of the light (the paper's (A_i - A_ij) B + A_ij t B), and
// the influences of several clusters multiply. With b = 0 the beam is a
// single ray: a cluster it passes through lets through t.
// The flux is Phi = sum over sources of intensity * product (intensities
// sum to 1) and the answer is p2 = e * A * Phi - c (e = "efficiency:");
// p1 is left as it was. As in chiba, the beams towards one source are cast
// together through a grid across that direction (light_columns.h) rather
// than the manual's voxel grid; "grid size:" is read but changes nothing.
#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>

#include "env/programs/light_columns.h"
#include "env/programs/light_parallel.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"
#include "env/programs/takenaka_parameters.h"

namespace sylva::env {

namespace {

using light::LightSource;
using light::Sphere;
using light::Vec3;

class Takenaka : public Field {
 public:
  explicit Takenaka(TakenakaParameters parameters) : p_(std::move(parameters)) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<Sphere> spheres = spheres_of(queries);
    double largest = 0;
    for (const Sphere& s : spheres) largest = std::max(largest, s.radius);
    double margin = p_.beam_radius * largest;  // the widest beam

    // All beams towards one source are cast together; each cluster's flux is
    // summed in source order, so the result does not depend on the threads.
    std::vector<double> flux(spheres.size(), 0);
    for (const LightSource& source : p_.sources) {
      columns_.build(spheres, source.direction, margin);
      std::span<const std::uint32_t> order = columns_.casting_order();
      light::parallel_for(order.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
          std::uint32_t i = order[k];
          double intensity = source.intensity;
          columns_.for_each_near(i, 0, p_.beam_radius * spheres[i].radius, [&](const light::LightColumns::Neighbour& n) {
            intensity *= transmitted(spheres[i], n, spheres[n.sphere]);
          });
          flux[i] += intensity;
        }
      });
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
      double area = queries[i].module.parameters[0];
      double cost = queries[i].module.parameters[1];
      answers[i].assign(1, static_cast<float>(p_.efficiency * area * flux[i] - cost));
    }
    if (p_.verbose) {
      std::cerr << "takenaka: step " << step << ": " << spheres.size() << " clusters, " << p_.sources.size()
                << " sources\n";
    }
  }

 private:
  std::vector<Sphere> spheres_of(std::span<const Query> queries) const {
    std::vector<Sphere> spheres;
    spheres.reserve(queries.size());
    for (const Query& q : queries) {
      if (q.module.parameters.size() < 2) {
        fail_module("takenaka", q,
                    "has " + std::to_string(q.module.parameters.size()) +
                        " parameters; expected 4 (the cluster's area, its maintenance cost, and two more)");
      }
      double area = q.module.parameters[0];
      if (area < 0) {
        std::ostringstream problem;
        problem << "gives the area " << area << "; expected 0 or more";
        fail_module("takenaka", q, problem.str());
      }
      spheres.push_back({light::to_vec3(turtle_position(q, "takenaka")), p_.sparsity * std::sqrt(area / std::numbers::pi)});
    }
    return spheres;
  }

  // The part of the beam from `from` that `other`, at `where`, lets through.
  double transmitted(const Sphere& from, const light::LightColumns::Neighbour& where, const Sphere& other) const {
    if (where.along <= 0 || other.radius <= 0) return 1;  // not between the cluster and the source
    double beam = p_.beam_radius * from.radius;
    double reach = beam + other.radius;
    if (where.distance_squared >= reach * reach) return 1;  // the disks are apart
    double covered = 0;  // fraction of the beam's cross-section
    if (beam > 0) {
      covered = light::disk_overlap_area(beam, other.radius, std::sqrt(where.distance_squared)) /
                (std::numbers::pi * beam * beam);
    } else {
      covered = where.distance_squared < other.radius * other.radius ? 1 : 0;
    }
    return 1 - covered * (1 - p_.transmittance);
  }

  TakenakaParameters p_;
  light::LightColumns columns_;  // kept from pass to pass to reuse its memory
};

}  // namespace

std::unique_ptr<Field> make_takenaka(const ProgramInvocation& invocation) {
  return std::make_unique<Takenaka>(read_takenaka_parameters(parameter_file_path(invocation, "takenaka", ParameterDialect::light)));
}

}  // namespace sylva::env
