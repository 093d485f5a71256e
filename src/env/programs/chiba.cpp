// chiba: direct light reaching spheres in 3D (EnviroManual 3.2.2, after
// Chiba et al. 1994). Every query is a sphere at the turtle position with
// radius p1 (the file's default radius when p1 is 0). From each centre a ray
// is cast towards every light source; each other sphere it passes reduces the
// intensity carried by the ray. The answer is p1 = the light reaching the
// centre as a fraction of the whole sky (source intensities sum to 1) and,
// for modules with 4 parameters, p2..p4 = the brightest direction: the sum of
// the ray directions weighted by the light they bring, made unit length.
#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>

#include "env/programs/chiba_parameters.h"
#include "env/programs/light_columns.h"
#include "env/programs/light_parallel.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {

namespace {

using light::LightSource;
using light::Sphere;
using light::Vec3;

class Chiba : public Field {
 public:
  explicit Chiba(ChibaParameters parameters) : p_(std::move(parameters)) {
    sources_ = p_.sources.empty() ? light::sky_sources(p_.samples, p_.lower_to_upper, p_.cie_overcast) : p_.sources;
    log_transmittance_ = p_.transmittance > 0 ? std::log(p_.transmittance) : 0;
  }

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<Sphere> spheres = spheres_of(queries);
    double largest = 0;
    for (const Sphere& s : spheres) largest = std::max(largest, s.radius);
    // The widest a ray's test reaches beyond a sphere's own radius: the beam
    // (a fraction of the shooting sphere's radius), or the shooting sphere's
    // whole disk when intersection areas are estimated.
    double margin = p_.estimate_intersection_area ? largest : p_.beam_radius * largest;
    // A sphere whose centre is behind a ray's origin can still hold part of
    // the ray; with estimated areas only spheres ahead count.
    double behind = p_.estimate_intersection_area ? 0 : largest + margin;

    // All rays towards one source are cast together; each query's sums are
    // kept in source order, so the result does not depend on the threads.
    std::vector<double> total(spheres.size(), 0);
    std::vector<Vec3> brightest(spheres.size());
    for (const LightSource& source : sources_) {
      columns_.build(spheres, source.direction, margin);
      std::span<const std::uint32_t> order = columns_.casting_order();
      light::parallel_for(order.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
          std::uint32_t i = order[k];
          // pow(t, x1) * pow(t, x2) * ... = pow(t, x1 + x2 + ...)
          double exponent = 0;
          columns_.for_each_near(i, behind, ray_width(spheres[i]), [&](const light::LightColumns::Neighbour& n) {
            exponent += transmittance_exponent(spheres[i], n, spheres[n.sphere]);
          });
          double intensity = source.intensity * transmitted(exponent);
          total[i] += intensity;
          brightest[i] = brightest[i] + intensity * source.direction;
        }
      });
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
      if (queries[i].module.parameters.empty()) continue;
      answers[i].assign(0, static_cast<float>(total[i]));
      if (queries[i].module.parameters.size() >= 4) {
        Vec3 d = light::normalized(brightest[i]);
        answers[i].assign(1, static_cast<float>(d.x));
        answers[i].assign(2, static_cast<float>(d.y));
        answers[i].assign(3, static_cast<float>(d.z));
      }
    }
    if (p_.verbose) {
      std::cerr << "chiba: step " << step << ": " << spheres.size() << " spheres, " << sources_.size()
                << " light directions\n";
    }
  }

 private:
  std::vector<Sphere> spheres_of(std::span<const Query> queries) const {
    std::vector<Sphere> spheres;
    spheres.reserve(queries.size());
    for (const Query& q : queries) {
      double radius = query_parameter(q, 0);
      if (radius < 0) {
        std::ostringstream problem;
        problem << "gives the sphere radius " << radius << "; expected 0 (the default radius) or more";
        fail_module("chiba", q, problem.str());
      }
      if (radius == 0) radius = p_.radius;
      spheres.push_back({light::to_vec3(turtle_position(q, "chiba")), radius});
    }
    return spheres;
  }

  // How far beyond its own radius another sphere can be and still dim the
  // ray of `from`: the beam, or the whole disk of `from` when intersection
  // areas are estimated.
  double ray_width(const Sphere& from) const {
    return p_.estimate_intersection_area ? from.radius : p_.beam_radius * from.radius;
  }

  // How much sphere `other`, at `where` from the ray of `from`, dims the ray:
  // the exponent x of pow(t, x). x is the length of the ray inside `other`
  // (its radius grown by the beam) over the diameter of `other`, or, when
  // intersection areas are estimated, the part of the shooting sphere's disk
  // that the disk of `other` covers, both projected along the ray.
  double transmittance_exponent(const Sphere& from, const light::LightColumns::Neighbour& where,
                                const Sphere& other) const {
    if (p_.estimate_intersection_area) {
      double reach = from.radius + other.radius;
      if (where.along <= 0 || where.distance_squared >= reach * reach) return 0;  // behind, or disks apart
      double covered = light::disk_overlap_area(from.radius, other.radius, std::sqrt(where.distance_squared));
      return covered / (std::numbers::pi * from.radius * from.radius);
    }
    if (other.radius <= 0) return 0;
    double inside = light::chord_ahead({where.along, where.distance_squared},
                                       other.radius + p_.beam_radius * from.radius);
    return inside / (2 * other.radius);
  }

  // pow(t, exponent), with no light through opaque spheres that were hit.
  double transmitted(double exponent) const {
    if (exponent <= 0) return 1;
    if (p_.transmittance <= 0) return 0;
    return std::exp(exponent * log_transmittance_);
  }

  ChibaParameters p_;
  std::vector<LightSource> sources_;
  double log_transmittance_ = 0;
  light::LightColumns columns_;  // kept from pass to pass to reuse its memory
};

}  // namespace

std::unique_ptr<Field> make_chiba(const ProgramInvocation& invocation) {
  return std::make_unique<Chiba>(read_chiba_parameters(parameter_file_path(invocation, "chiba", ParameterDialect::light)));
}

}  // namespace sylva::env
