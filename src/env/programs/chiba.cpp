// chiba (EnviroManual 3.2.2; the Virtual Laboratory's ENVIRO/chiba, after
// Chiba et al. 1994): light reaching leaf clusters, balls in 3D, through the
// other clusters. Computed as the real program computes it.
//
// Query:  ?E(radius) or ?E(radius, x, y, z[, ...]) at the turtle position,
//         which the .e file must send with three values; a radius not above
//         0 takes the file's "radius:". Other parameter counts get no answer.
// Answer: p1 = the light reaching the cluster's centre (the rays' intensities
//         sum to 1), and for four parameters or more p2..p4 = the brightest
//         direction: the rays' directions weighted by the light each brings,
//         made unit length.
//
// From each cluster's centre a ray goes towards each light direction
// (chiba_parameters.h); each other cluster it meets dims it:
//  - by t^(l / 2(R + b·r)), with l the length of the ray inside the other
//    cluster grown by b·r (R its radius, r the shooting cluster's, b the
//    beam radius, t the transmittance), counting only the part ahead;
//  - or, with "estimate intersection area: on", by 1 - (1 - t)·A/(π r²), A
//    the area where the two clusters' disks, seen along the ray, overlap,
//    for clusters whose centre is not behind the shooting one.
// Clusters are found by walking a voxel grid fitted around them along the
// ray, as the real program walks it. Its walk has a slip that Sylva keeps,
// since it decides which clusters a ray meets: the voxel centres it measures
// the next crossing from ignore where the grid starts, so unless the grid
// starts at 0 the walk may leave a voxel on the wrong face and pass by
// clusters the ray goes through (or reach voxels it does not cross). A
// cluster is entered in every voxel whose centre lies within its radius, grown
// by the beam and half a voxel diagonal; one it reaches through several
// voxels dims a ray once.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>

#include "env/programs/chiba_parameters.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {

namespace {

constexpr const char* kProgram = "chiba";

using Vec = std::array<float, 3>;

struct Cluster {
  Vec position{};
  float radius = 0;
  float area = 0;  // π r², in float
  std::size_t query = 0;
  bool wants_direction = false;  // four parameters or more
};

// The voxel grid around a pass's clusters, with the clusters of each voxel.
struct VoxelGrid {
  std::array<int, 3> size{1, 1, 1};
  Vec position{};  // the lowest corner
  Vec range{};     // the extent along each axis
  std::vector<std::uint32_t> start;     // per voxel, where its clusters begin in `clusters`
  std::vector<std::uint32_t> clusters;  // in the order they were entered

  int index(int x, int y, int z) const { return (z * size[1] + y) * size[0] + x; }
};

// floor() of a float, as C's floor takes it, converted to int (kept within
// int: the real program's conversion of a value beyond it is undefined).
int floor_to_int(double value) {
  if (!(value == value)) return 0;
  return static_cast<int>(std::fmax(std::fmin(std::floor(value), 2e9), -2e9));
}

class Chiba : public Field {
 public:
  explicit Chiba(ChibaSettings settings) : s_(std::move(settings)) { grid_.size = s_.grid_size; }

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    store(queries);
    if (clusters_.empty()) return;
    build_grid();
    signature_.assign(clusters_.size(), 0);
    ray_ = 0;
    for (std::size_t i = 0; i < clusters_.size(); ++i) {
      const Cluster& cluster = clusters_[i];
      float sum = 0;
      Vec brightest{};
      for (const ChibaRay& ray : s_.rays) {
        const float light = light_along(i, ray);
        sum += light;
        for (int c = 0; c < 3; ++c) brightest[c] += light * ray.direction[c];
      }
      Answer& answer = answers[cluster.query];
      answer.assign(0, sum);
      if (cluster.wants_direction) {
        const float length =
            static_cast<float>(std::sqrt(static_cast<double>(brightest[0] * brightest[0] + brightest[1] * brightest[1] +
                                                             brightest[2] * brightest[2])));
        for (int c = 0; c < 3; ++c) answer.assign(1 + c, length > 0 ? brightest[c] / length : brightest[c]);
      }
    }
    if (s_.verbose)
      std::cerr << kProgram << ": pass before step " << step + 1 << ": " << clusters_.size() << " clusters, "
                << s_.rays.size() << " light directions\n";
  }

 private:
  void store(std::span<const Query> queries) {
    clusters_.clear();
    std::size_t without_position = 0, unusable = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const Query& query = queries[q];
      const std::size_t count = query.module.parameters.size();
      if (count != 1 && count < 4) {
        ++unusable;
        continue;
      }
      if (query.turtle.position_count < 3) {
        ++without_position;
        continue;
      }
      Cluster cluster;
      cluster.position = query.turtle.position;
      const float radius = query.module.parameters[0];
      cluster.radius = radius > 0 ? radius : s_.radius;
      cluster.area = static_cast<float>(std::numbers::pi * cluster.radius * cluster.radius);
      cluster.query = q;
      cluster.wants_direction = count >= 4;
      // The grid grows to hold each cluster's box, in float.
      if (clusters_.empty()) {
        for (int c = 0; c < 3; ++c) {
          grid_.position[c] = cluster.position[c] - cluster.radius;
          grid_.range[c] = 2 * cluster.radius;
        }
        max_radius_ = cluster.radius;
      } else {
        for (int c = 0; c < 3; ++c) {
          const float below = grid_.position[c] - (cluster.position[c] - cluster.radius);
          if (below > 0) {
            grid_.position[c] -= below;
            grid_.range[c] += below;
          }
          const float above = (cluster.position[c] + cluster.radius) - (grid_.position[c] + grid_.range[c]);
          if (above > 0) grid_.range[c] += above;
        }
        if (cluster.radius > max_radius_) max_radius_ = cluster.radius;
      }
      clusters_.push_back(cluster);
    }
    if (unusable > 0)
      warn_once(warned_parameters_, std::to_string(unusable) +
                                        " communication modules get no answer: chiba needs one parameter or four");
    if (without_position > 0)
      warn_once(warned_position_, std::to_string(without_position) +
                                      " communication modules get no answer: the .e file does not send the turtle "
                                      "position with three values ('turtle position: %g %g %g')");
  }

  // Enters each cluster in the voxels around it (the real InitializeGrid).
  void build_grid() {
    VoxelGrid& g = grid_;
    float half = 0;
    for (int c = 0; c < 3; ++c) {
      const float voxel = g.range[c] / static_cast<float>(g.size[c]);
      half += voxel * voxel;
    }
    half = static_cast<float>(0.5 * std::sqrt(static_cast<double>(half)));
    const float beam = max_radius_ * s_.beam_radius;
    const std::size_t voxels = static_cast<std::size_t>(g.size[0]) * g.size[1] * g.size[2];
    g.start.assign(voxels + 1, 0);
    std::vector<std::array<int, 6>> bounds(clusters_.size());
    for (std::size_t i = 0; i < clusters_.size(); ++i) {
      const Cluster& cluster = clusters_[i];
      for (int c = 0; c < 3; ++c) {
        const float scale = static_cast<float>(g.size[c]);
        const float low = (cluster.position[c] - cluster.radius - beam - g.position[c]) / g.range[c] * scale;
        const float high = (cluster.position[c] + cluster.radius + beam - g.position[c]) / g.range[c] * scale;
        bounds[i][c] = std::max(floor_to_int(low) - 1, 0);
        bounds[i][3 + c] = std::min(1 + floor_to_int(high), g.size[c] - 1);
      }
    }
    auto each_voxel = [&](std::size_t i, auto&& enter) {
      const Cluster& cluster = clusters_[i];
      const float reach = cluster.radius + beam + half;
      Vec centre;
      for (int z = bounds[i][2]; z <= bounds[i][5]; ++z) {
        centre[2] = voxel_centre(2, z);
        for (int y = bounds[i][1]; y <= bounds[i][4]; ++y) {
          centre[1] = voxel_centre(1, y);
          for (int x = bounds[i][0]; x <= bounds[i][3]; ++x) {
            centre[0] = voxel_centre(0, x);
            float distance = 0;
            for (int c = 0; c < 3; ++c) {
              const float d = cluster.position[c] - centre[c];
              distance = c == 0 ? d * d : distance + d * d;
            }
            if (distance <= reach * reach) enter(g.index(x, y, z));
          }
        }
      }
    };
    for (std::size_t i = 0; i < clusters_.size(); ++i) each_voxel(i, [&](int v) { ++g.start[v + 1]; });
    for (std::size_t v = 0; v < voxels; ++v) g.start[v + 1] += g.start[v];
    g.clusters.resize(g.start[voxels]);
    std::vector<std::uint32_t> filled(g.start.begin(), g.start.end() - 1);
    for (std::size_t i = 0; i < clusters_.size(); ++i)
      each_voxel(i, [&](int v) { g.clusters[filled[v]++] = static_cast<std::uint32_t>(i); });
  }

  float voxel_centre(int axis, int k) const {
    return static_cast<float>(grid_.position[axis] +
                              (static_cast<float>(k) + 0.5) / static_cast<float>(grid_.size[axis]) * grid_.range[axis]);
  }

  // The light cluster `from` receives from one direction (the real
  // IntensityFromSample).
  float light_along(std::size_t from, const ChibaRay& ray) {
    if (ray.intensity == 0) return 0;
    const Cluster& leaf = clusters_[from];
    const VoxelGrid& g = grid_;
    const Vec& d = ray.direction;
    const Vec& origin = leaf.position;
    std::array<int, 3> step{1, g.size[0], g.size[0] * g.size[1]};
    Vec half_voxel, middle;
    std::array<int, 3> node;
    for (int c = 0; c < 3; ++c) {
      half_voxel[c] = static_cast<float>(0.5 * g.range[c] / static_cast<float>(g.size[c]));
      if (d[c] < 0) {
        half_voxel[c] = -half_voxel[c];
        step[c] = -step[c];
      }
    }
    for (int c = 0; c < 3; ++c) {
      node[c] = floor_to_int((origin[c] - g.position[c]) / g.range[c] * static_cast<float>(g.size[c]));
      // The slip: measured from 0, not from the grid's corner.
      middle[c] = static_cast<float>((static_cast<float>(node[c]) + 0.5) / static_cast<float>(g.size[c]) * g.range[c]);
    }
    long voxel = g.index(std::clamp(node[0], 0, g.size[0] - 1), std::clamp(node[1], 0, g.size[1] - 1),
                         std::clamp(node[2], 0, g.size[2] - 1));
    const long voxels = static_cast<long>(g.start.size()) - 1;
    float reduction = 1;
    const std::uint64_t signature = ++ray_;
    signature_[from] = signature;
    for (;;) {
      // A walk that strays off the grid (possible only from a cluster on its
      // upper face) reads memory beyond it in the real program; here it meets nothing.
      if (voxel >= 0 && voxel < voxels) {
        // The real program's lists hold the last entered cluster first.
        for (std::uint32_t k = g.start[voxel + 1]; k-- > g.start[voxel];) {
          const std::uint32_t other = g.clusters[k];
          if (signature_[other] == signature) continue;
          if (s_.estimate_area) {
            const float covered = covered_area(origin, d, clusters_[other], leaf.radius);
            if (covered > 0) {
              signature_[other] = signature;
              reduction *= 1 - (1 - s_.transmittance) * covered / leaf.area;
            }
          } else {
            const float inside = length_inside(origin, d, clusters_[other], leaf.radius);
            if (inside > 0) {
              signature_[other] = signature;
              reduction = static_cast<float>(
                  reduction * std::pow(static_cast<double>(s_.transmittance),
                                       inside / (2.0 * (clusters_[other].radius + s_.beam_radius * leaf.radius))));
            }
          }
        }
      }
      // The face the ray leaves the voxel by.
      int axis = 0;
      float nearest = std::fabs(middle[0] + half_voxel[0] - origin[0]);
      for (int c = 1; c < 3; ++c) {
        const float to_face = middle[c] + half_voxel[c] - origin[c];
        if (std::fabs(to_face * d[axis]) < std::fabs(nearest * d[c])) {
          nearest = to_face;
          axis = c;
        }
      }
      middle[axis] += 2 * half_voxel[axis];
      voxel += step[axis];
      node[axis] += d[axis] > 0 ? 1 : -1;
      if (node[axis] < 0 || node[axis] >= g.size[axis]) return ray.intensity * reduction;
    }
  }

  // The length of the ray from `origin` along `d` inside `other`, its radius
  // grown by the beam, ahead of the origin (the real IsClusterIntersection).
  float length_inside(const Vec& origin, const Vec& d, const Cluster& other, float radius) const {
    Vec v;
    for (int c = 0; c < 3; ++c) v[c] = origin[c] - other.position[c];
    const float along = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    const float reach = other.radius + radius * s_.beam_radius;
    float discriminant = along * along - (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + reach * reach;
    if (discriminant >= 0) {
      discriminant = static_cast<float>(std::sqrt(static_cast<double>(discriminant)));
      if (-along + discriminant > 0) return -along - discriminant >= 0 ? 2 * discriminant : -along + discriminant;
    }
    return 0;
  }

  // The area where the disks of `other` and of the shooting cluster (radius
  // `radius`) overlap seen along the ray, 0 when `other` lies behind (the
  // real ComputeCoveredArea).
  static float covered_area(const Vec& origin, const Vec& d, const Cluster& other, float radius) {
    Vec v;
    for (int c = 0; c < 3; ++c) v[c] = origin[c] - other.position[c];
    const float along = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    if (along > 0) return 0;
    float apart = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - along * along;
    const float reach = other.radius + radius;
    if (!(apart < reach * reach)) return 0;
    const float r1 = other.radius < radius ? radius : other.radius;
    const float r2 = other.radius < radius ? other.radius : radius;
    const float r2s = r2 * r2, r1s = r1 * r1;
    apart = static_cast<float>(std::sqrt(static_cast<double>(apart)));
    if (apart + r2 <= r1) return static_cast<float>(std::numbers::pi * r2s);  // the smaller disk inside
    const float x1 = (r1s + apart * apart - r2s) / (2 * apart);
    const float x2 = (r2s + apart * apart - r1s) / (2 * apart);
    const float y = static_cast<float>(std::sqrt(static_cast<double>(r2s - x2 * x2)));
    return static_cast<float>(r1s * std::acos(static_cast<double>(x1 / r1)) +
                              r2s * std::acos(static_cast<double>(x2 / r2)) - y * apart);
  }

  static void warn_once(bool& warned, const std::string& message) {
    if (warned) return;
    warned = true;
    std::cerr << "warning: " << kProgram << ": " << message << "\n";
  }

  ChibaSettings s_;
  std::vector<Cluster> clusters_;
  float max_radius_ = 0;
  VoxelGrid grid_;
  std::vector<std::uint64_t> signature_;  // per cluster, the last ray that met it
  std::uint64_t ray_ = 0;
  bool warned_parameters_ = false;
  bool warned_position_ = false;
};

}  // namespace

std::unique_ptr<Field> make_chiba(const ProgramInvocation& invocation) {
  return std::make_unique<Chiba>(read_chiba_settings(vlab_spec_file_path(invocation, kProgram)));
}

}  // namespace sylva::env
