// Generalized cylinders (LPFG manual 5.8, CPFG manual 6.7.3): StartGC,
// PointGC and EndGC (cpfg's @Gs @Gc @Ge, {(t) .(s) }(t)) record control
// points (the turtle's position, frame, width and contour at each); the
// cylinder is drawn when it ends, a ring of contour points per control point,
// joined by bands of triangles.
//
// Between two control points the axis is the cubic Hermite curve through
// them, its tangents along the turtle's heading at each, of length the
// distance between them times @Gt's coefficients (1.2 by default). A stretch
// of `strips` bands (cpfg's @Gc(strips); 1 by default and always in L+C,
// whose manual describes no interpolation) has `strips - 1` rings inside at
// t = k / strips: their frames are the first control point's carried along
// the curve by parallel transport, with the roll between the two control
// frames spread evenly; their contour scale and contour go linearly from one
// control point to the next, and so does their radius unless @Gr shaped it
// (geometry/radius_profile.h). One strip is a straight band.
#include "turtle/cylinder_builder.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/face_normals.h"
#include "geometry/generalized_cylinder.h"
#include "support/diagnostic.h"
#include "turtle/model_error_text.h"

namespace sylva::turtle {

namespace {

constexpr int kStepStrips = 4;  // the strips of the points after F and f

// Whether the turtle is away from a cylinder's last control point (or the
// cylinder has none yet).
template <class Points>
bool moved_since_last_point(const Points& points, Vec3 position) {
  return points.empty() || length(position - points.back().position) >= kEpsilon;
}

// The number of rings of a cylinder: one per control point and strips - 1
// inside each stretch; a closed axis has a stretch back to the first point
// (ending at its ring).
template <class Points>
std::size_t ring_count(const Points& points, bool loop) {
  if (points.size() < 2) return points.size();
  std::size_t rings = loop ? 0 : 1;
  for (std::size_t k = loop ? 0 : 1; k < points.size(); ++k) rings += static_cast<std::size_t>(points[k].strips);
  return rings;
}

bool closed_axis(int type) { return type == 2 || type == 4; }
bool bspline_axis(int type) { return type == 3 || type == 4; }

// The right-handed angle around unit `axis` taking `from` to `to` (both
// across the axis).
float angle_around(Vec3 axis, Vec3 from, Vec3 to) {
  return std::atan2(dot(cross(from, to), axis), dot(from, to));
}

}  // namespace

CylinderBuilder::CylinderBuilder(const TurtleSettings& settings, geometry::Scene* scene)
    : settings_(settings), scene_(scene) {}

void CylinderBuilder::check_contour(int id, const char* module, geometry::Provenance from) const {
  const std::size_t count = settings_.contours ? settings_.contours->size() : 0;
  if (id == 0 || (id >= 1 && static_cast<std::size_t>(id) <= count)) return;
  throw ModelError(std::string(module) + where(from) + ": there is no contour " + std::to_string(id) +
                   (count ? " (contours are 1 to " + std::to_string(count) + ", 0 is the circle)"
                          : " (no contour files are given; 0 is the circle)"));
}

const geometry::Contour& CylinderBuilder::contour(int id) const {
  static const geometry::Contour kCircle = geometry::Contour::circle();
  if (id <= 0 || !settings_.contours || static_cast<std::size_t>(id) > settings_.contours->size()) return kCircle;
  return (*settings_.contours)[static_cast<std::size_t>(id) - 1];
}

// The contour resampled to `sides` points, blended toward a second one.
// Resamplings are kept: a cylinder asks for the same few at every ring.
const Vec3* CylinderBuilder::contour_points(int id, int blend_id, float blend, int sides) {
  auto resampled = [&](int which) -> const std::vector<Vec3>& {
    for (const ResampledContour& r : resampled_)
      if (r.id == which && r.sides == sides) return r.points;
    resampled_.push_back(ResampledContour{which, sides, contour(which).resample(sides)});
    return resampled_.back().points;
  };
  const std::vector<Vec3>& a = resampled(id);
  if (blend == 0 || blend_id == id) return a.data();
  const std::vector<Vec3>& b = resampled(blend_id);
  blended_.resize(static_cast<std::size_t>(sides));
  for (std::size_t k = 0; k < blended_.size(); ++k) blended_[k] = a[k] * (1 - blend) + b[k] * blend;
  return blended_.data();
}

CylinderBuilder::ControlPoint CylinderBuilder::control_point(const TurtleState& state, geometry::Provenance from,
                                                             int strips) {
  ControlPoint p;
  p.position = state.position;
  p.frame = state.frame;
  p.width = state.width;
  p.contour = state.contour;
  p.blend_contour = state.blend_contour;
  p.blend = state.blend;
  p.scale_left = state.contour_scale_left;
  p.scale_up = state.contour_scale_up;
  p.color = state.color;
  p.back_color = state.back_color;
  p.from = from;
  p.strips = std::max(1, strips);
  p.tangent_start = state.cylinder_tangent_start;
  p.tangent_end = state.cylinder_tangent_end;
  p.radius_tangents = state.radius_tangents;
  return p;
}

CylinderBuilder::Closed CylinderBuilder::start(TurtleState& state, const TurtleState* parent, int type,
                                               geometry::Provenance from) {
  Closed closed;
  if (open(state)) {
    const bool inherited =
        parent && parent->cylinder == state.cylinder && parent->cylinder_serial == state.cylinder_serial;
    if (!inherited) closed = close(state.cylinder);
  }
  std::size_t slot = 0;
  while (slot < cylinders_.size() && cylinders_[slot].open) ++slot;
  if (slot == cylinders_.size()) cylinders_.emplace_back();
  Cylinder& c = cylinders_[slot];
  c.points.clear();
  c.open = true;
  c.type = type;
  c.serial = next_serial_++;
  const geometry::Contour& shape = contour(state.contour);
  int sides = state.contour_sides > 0 ? state.contour_sides : shape.samples > 0 ? shape.samples : settings_.contour_sides;
  c.sides = std::max(3, sides);
  // {(type) "does not define the first control point" (CPFG manual 6.7.3).
  if (type == 0) c.points.push_back(control_point(state, from, 1));
  state.cylinder = static_cast<int>(slot);
  state.cylinder_serial = c.serial;
  return closed;
}

int CylinderBuilder::add_point(const TurtleState& state, geometry::Provenance from, int strips) {
  if (!open(state)) return 0;
  Cylinder& c = cylinders_[static_cast<std::size_t>(state.cylinder)];
  c.points.push_back(control_point(state, from, strips));
  return static_cast<int>(c.points.size());
}

CylinderBuilder::Dot CylinderBuilder::dot(const TurtleState& state, geometry::Provenance from, int strips) {
  if (!open(state)) return {};
  Cylinder& c = cylinders_[static_cast<std::size_t>(state.cylinder)];
  if (c.type > 0 && !moved_since_last_point(c.points, state.position)) {
    // The point the last F or f made: .(strips) gives its stretch's strips.
    c.points.back().strips = std::max(1, strips);
    return Dot{static_cast<int>(c.points.size()), true};
  }
  return Dot{add_point(state, from, strips), false};
}

int CylinderBuilder::step_point(const TurtleState& state, geometry::Provenance from) {
  if (!open(state)) return 0;
  Cylinder& c = cylinders_[static_cast<std::size_t>(state.cylinder)];
  if (c.type == 0 || !moved_since_last_point(c.points, state.position)) return 0;
  c.points.push_back(control_point(state, from, kStepStrips));
  return static_cast<int>(c.points.size());
}

CylinderBuilder::Ended CylinderBuilder::end(TurtleState& state, geometry::Provenance from, int strips, int type) {
  Cylinder& c = cylinders_[static_cast<std::size_t>(state.cylinder)];
  Ended ended;
  ended.opened_type = c.type;
  if (c.type == 0) {
    // @Gs ... @Ge(strips) or }(type), @Ge's equivalent: always a last point.
    c.points.push_back(control_point(state, from, type > 0 ? 1 : strips));
  } else if (moved_since_last_point(c.points, state.position)) {
    c.points.push_back(control_point(state, from, type > 0 ? kStepStrips : strips));
  }
  ended.closed = close(state.cylinder);
  state.cylinder = -1;
  return ended;
}

CylinderBuilder::Closed CylinderBuilder::close(int slot) {
  Cylinder& c = cylinders_[static_cast<std::size_t>(slot)];
  const Closed closed{static_cast<int>(ring_count(c.points, closed_axis(c.type))), c.sides};
  draw(slot);
  c.open = false;
  return closed;
}

void CylinderBuilder::draw(int slot) {
  const Cylinder& c = cylinders_[static_cast<std::size_t>(slot)];
  if (!scene_ || c.points.size() < 2) return;
  const int sides = c.sides;
  const auto n_sides = static_cast<std::size_t>(sides);
  const std::size_t n = c.points.size();
  const bool loop = closed_axis(c.type);
  const bool bspline = bspline_axis(c.type);
  const ControlPoint& head = c.points.front();
  const bool closed = contour(head.contour).closed;
  // Bands face outward for a counter-clockwise contour; a clockwise one is
  // turned the other way.
  const bool reverse =
      closed && geometry::contour_orientation(contour_points(head.contour, head.blend_contour, head.blend, sides),
                                              sides) < 0;

  // The B-spline's control polygon: the control points, wrapped around a
  // closed axis; an open one gets phantom points 2 p0 - p1 and
  // 2 p(n-1) - p(n-2) beyond its ends, so that it starts and ends at them.
  auto control = [&](long i) -> Vec3 {
    const long count = static_cast<long>(n);
    if (loop) return c.points[static_cast<std::size_t>(((i % count) + count) % count)].position;
    if (i < 0) return c.points[0].position * 2.0f - c.points[1].position;
    if (i >= count) return c.points[n - 1].position * 2.0f - c.points[n - 2].position;
    return c.points[static_cast<std::size_t>(i)].position;
  };
  auto bspline_segment = [&](std::size_t k) {
    const auto i = static_cast<long>(k);
    return geometry::BSplineSegment{control(i - 1), control(i), control(i + 1), control(i + 2)};
  };
  // Where a control point's ring goes: at the point on a Hermite axis; on a
  // B-spline, where the curve passes nearest it (its segment's start), its
  // frame turned to the curve.
  struct Anchor {
    Vec3 position;
    Frame frame;
  };
  auto anchor = [&](std::size_t k) {
    const ControlPoint& p = c.points[k];
    Anchor a{p.position, p.frame};
    if (bspline) {
      const geometry::BSplineSegment s = bspline_segment(k);
      a.position = s.at(0);
      a.frame.set_heading(s.derivative(0), kEpsilon);
      a.frame.orthonormalize();
    }
    return a;
  };

  const auto first_vertex = static_cast<std::uint32_t>(scene_->positions.size());
  auto control_ring = [&](const ControlPoint& p, const Anchor& at) {
    const float radius = p.width / 2;  // the width is the diameter, as for lines
    geometry::place_ring(contour_points(p.contour, p.blend_contour, p.blend, sides), sides, at.position,
                         at.frame.heading, at.frame.left, at.frame.up, radius * p.scale_left, radius * p.scale_up,
                         scene_->positions);
  };
  Anchor from = anchor(0);
  control_ring(head, from);
  const auto first_index = static_cast<std::uint32_t>(scene_->indices.size());
  const std::size_t stretches = loop ? n : n - 1;
  for (std::size_t k = 0; k < stretches; ++k) {
    const ControlPoint& a = c.points[k];
    const bool back_to_head = k + 1 == n;  // a closed axis's last stretch
    const ControlPoint& b = c.points[back_to_head ? 0 : k + 1];
    const Anchor to = anchor(back_to_head ? 0 : k + 1);
    const auto stretch_first = static_cast<std::uint32_t>(scene_->positions.size()) - static_cast<std::uint32_t>(sides);
    const float distance = length(to.position - from.position);
    // Rings inside the stretch: none when the ends coincide (the curve has
    // no length to spread them along).
    const int strips = distance < kEpsilon ? 1 : b.strips;
    if (strips > 1) {
      const geometry::HermiteSegment hermite{a.position, a.frame.heading * (distance * b.tangent_start), b.position,
                                             b.frame.heading * (distance * b.tangent_end)};
      const geometry::BSplineSegment spline = bspline_segment(k);
      auto curve_at = [&](float t) { return bspline ? spline.at(t) : hermite.at(t); };
      auto curve_derivative = [&](float t) { return bspline ? spline.derivative(t) : hermite.derivative(t); };
      // The contours at both ends, kept: contour_points reuses its buffer.
      const Vec3* from_points = contour_points(a.contour, a.blend_contour, a.blend, sides);
      ring_from_.assign(from_points, from_points + sides);
      const Vec3* to_points = contour_points(b.contour, b.blend_contour, b.blend, sides);
      ring_to_.assign(to_points, to_points + sides);
      ring_between_.resize(n_sides);
      // Parallel transport of the first frame along the curve, then the roll
      // left between it and the last frame, spread over the stretch.
      std::vector<Frame>& frames = stretch_frames_;
      frames.resize(static_cast<std::size_t>(strips) + 1);
      frames[0] = from.frame;
      for (int j = 1; j <= strips; ++j) {
        const float t = static_cast<float>(j) / static_cast<float>(strips);
        Frame f = frames[static_cast<std::size_t>(j) - 1];
        Vec3 direction = j == strips ? to.frame.heading : curve_derivative(t);
        if (length(direction) < kEpsilon * distance)
          direction = from.frame.heading * (1 - t) + to.frame.heading * t;
        f.set_heading(direction, kEpsilon);  // unchanged where the curve stops and the headings cancel
        f.orthonormalize();
        frames[static_cast<std::size_t>(j)] = f;
      }
      const Frame& carried = frames.back();
      const float roll = angle_around(to.frame.heading, carried.up, to.frame.up);
      const float radius_a = a.width / 2, radius_b = b.width / 2;
      for (int j = 1; j < strips; ++j) {
        const float t = static_cast<float>(j) / static_cast<float>(strips);
        Frame f = frames[static_cast<std::size_t>(j)];
        f.rotate(f.heading, std::cos(roll * t), std::sin(roll * t));
        for (std::size_t i = 0; i < n_sides; ++i) ring_between_[i] = ring_from_[i] * (1 - t) + ring_to_[i] * t;
        const float radius = geometry::stretch_radius(b.radius_tangents, radius_a, radius_b, distance, t);
        const float scale_left = a.scale_left * (1 - t) + b.scale_left * t;
        const float scale_up = a.scale_up * (1 - t) + b.scale_up * t;
        geometry::place_ring(ring_between_.data(), sides, curve_at(t), f.heading, f.left, f.up, radius * scale_left,
                             radius * scale_up, scene_->positions);
      }
    }
    // The stretch's last ring: the next control point's, or on a closed
    // axis's last stretch the first ring again.
    if (!back_to_head) control_ring(b, to);
    // A group per stretch between control points, made by the module that
    // ended the stretch, so that each stretch knows its own module.
    geometry::TriangleGroup g;
    g.kind = geometry::TriangleGroup::Kind::GeneralizedCylinder;
    g.first_index = static_cast<std::uint32_t>(scene_->indices.size());
    for (int j = 0; j < strips; ++j) {
      const auto ring = stretch_first + static_cast<std::uint32_t>(j * sides);
      const auto next = back_to_head && j + 1 == strips ? first_vertex : ring + static_cast<std::uint32_t>(sides);
      geometry::join_rings(ring, next, sides, closed, reverse, scene_->indices);
    }
    g.index_count = static_cast<std::uint32_t>(scene_->indices.size()) - g.first_index;
    g.color = b.color;
    g.back_color = b.back_color;
    g.from = b.from;
    scene_->groups.push_back(g);
    from = to;
  }
  geometry::set_normals_from_faces(*scene_, first_vertex,
                                   static_cast<std::uint32_t>(scene_->positions.size()) - first_vertex, first_index,
                                   static_cast<std::uint32_t>(scene_->indices.size()) - first_index);
}

}  // namespace sylva::turtle
