// Generalized cylinders (LPFG manual 5.8): StartGC, PointGC and EndGC record
// control points (the turtle's position, frame, width and contour at each);
// the cylinder is drawn when it ends, one ring of contour points per control
// point, joined by bands of triangles.
#include <algorithm>
#include <string>

#include "geometry/face_normals.h"
#include "geometry/generalized_cylinder.h"
#include "support/diagnostic.h"
#include "turtle/interpreter_impl.h"

namespace sylva::turtle {

void TurtleInterpreter::Impl::check_contour(int id, const char* module) const {
  const std::size_t count = settings_.contours ? settings_.contours->size() : 0;
  if (id == 0 || (id >= 1 && static_cast<std::size_t>(id) <= count)) return;
  throw ModelError(std::string(module) + where() + ": there is no contour " + std::to_string(id) +
                   (count ? " (contours are 1 to " + std::to_string(count) + ", 0 is the circle)"
                          : " (no contour files are given; 0 is the circle)"));
}

const geometry::Contour& TurtleInterpreter::Impl::contour(int id) const {
  static const geometry::Contour kCircle = geometry::Contour::circle();
  if (id <= 0 || !settings_.contours || static_cast<std::size_t>(id) > settings_.contours->size()) return kCircle;
  return (*settings_.contours)[static_cast<std::size_t>(id) - 1];
}

// The contour resampled to `sides` points, blended toward a second one.
// Resamplings are kept: a cylinder asks for the same few at every ring.
const Vec3* TurtleInterpreter::Impl::contour_points(int id, int blend_id, float blend, int sides) {
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

bool TurtleInterpreter::Impl::cylinder_open(const TurtleState& s) const {
  if (s.cylinder < 0) return false;
  const Cylinder& c = cylinders_[static_cast<std::size_t>(s.cylinder)];
  return c.open && c.serial == s.cylinder_serial;
}

TurtleInterpreter::Impl::CylinderPoint TurtleInterpreter::Impl::control_point() const {
  CylinderPoint p;
  p.position = state_.position;
  p.frame = state_.frame;
  p.width = state_.width;
  p.contour = state_.contour;
  p.blend_contour = state_.blend_contour;
  p.blend = state_.blend;
  p.scale_left = state_.contour_scale_left;
  p.scale_up = state_.contour_scale_up;
  p.color = state_.color;
  p.from = from_;
  return p;
}

void TurtleInterpreter::Impl::start_cylinder() {
  // One cylinder at a time per branch: a new one in the same branch ends the
  // previous; one in a sub-branch leaves the parent's open.
  if (cylinder_open(state_)) {
    const bool inherited = !stack_.empty() && stack_.back().cylinder == state_.cylinder &&
                           stack_.back().cylinder_serial == state_.cylinder_serial;
    if (!inherited) close_cylinder(state_.cylinder);
  }
  std::size_t slot = 0;
  while (slot < cylinders_.size() && cylinders_[slot].open) ++slot;
  if (slot == cylinders_.size()) cylinders_.emplace_back();
  Cylinder& c = cylinders_[slot];
  c.points.clear();
  c.open = true;
  c.serial = next_serial_++;
  const geometry::Contour& shape = contour(state_.contour);
  int sides = state_.contour_sides > 0 ? state_.contour_sides : shape.samples > 0 ? shape.samples : settings_.contour_sides;
  c.sides = std::max(3, sides);
  c.points.push_back(control_point());
  state_.cylinder = static_cast<int>(slot);
  state_.cylinder_serial = c.serial;
  note_position(" at ", state_.position);
}

void TurtleInterpreter::Impl::cylinder_point() {
  if (!cylinder_open(state_)) {
    note(" ignored: no generalized cylinder");
    return;
  }
  Cylinder& c = cylinders_[static_cast<std::size_t>(state_.cylinder)];
  c.points.push_back(control_point());
  if (trace_) *trace_ += " point " + std::to_string(c.points.size());
  note_position(" at ", state_.position);
}

void TurtleInterpreter::Impl::end_cylinder() {
  if (!cylinder_open(state_)) {
    note(" ignored: no generalized cylinder");
    return;
  }
  Cylinder& c = cylinders_[static_cast<std::size_t>(state_.cylinder)];
  c.points.push_back(control_point());
  close_cylinder(state_.cylinder);
  state_.cylinder = -1;
}

void TurtleInterpreter::Impl::close_cylinder(int index) {
  Cylinder& c = cylinders_[static_cast<std::size_t>(index)];
  if (trace_)
    *trace_ += " cylinder of " + std::to_string(c.points.size()) + " rings x " + std::to_string(c.sides) + " sides";
  draw_cylinder(index);
  c.open = false;
}

void TurtleInterpreter::Impl::draw_cylinder(int index) {
  const Cylinder& c = cylinders_[static_cast<std::size_t>(index)];
  if (!scene_ || c.points.size() < 2) return;
  const int sides = c.sides;
  const CylinderPoint& head = c.points.front();
  const bool closed = contour(head.contour).closed;
  // Bands face outward for a counter-clockwise contour; a clockwise one is
  // turned the other way.
  const bool reverse =
      closed && geometry::contour_orientation(contour_points(head.contour, head.blend_contour, head.blend, sides),
                                              sides) < 0;

  const auto first_vertex = static_cast<std::uint32_t>(scene_->positions.size());
  for (const CylinderPoint& p : c.points) {
    const float radius = p.width / 2;  // the width is the diameter, as for lines
    geometry::place_ring(contour_points(p.contour, p.blend_contour, p.blend, sides), sides, p.position,
                         p.frame.heading, p.frame.left, p.frame.up, radius * p.scale_left, radius * p.scale_up,
                         scene_->positions);
  }
  const auto first_index = static_cast<std::uint32_t>(scene_->indices.size());
  // A group per stretch between control points, made by the module that
  // ended the stretch, so that each stretch knows its own module.
  for (std::size_t k = 0; k + 1 < c.points.size(); ++k) {
    geometry::TriangleGroup g;
    g.kind = geometry::TriangleGroup::Kind::GeneralizedCylinder;
    g.first_index = static_cast<std::uint32_t>(scene_->indices.size());
    const auto ring = first_vertex + static_cast<std::uint32_t>(k * static_cast<std::size_t>(sides));
    geometry::join_rings(ring, ring + static_cast<std::uint32_t>(sides), sides, closed, reverse, scene_->indices);
    g.index_count = static_cast<std::uint32_t>(scene_->indices.size()) - g.first_index;
    g.color = c.points[k + 1].color;
    g.from = c.points[k + 1].from;
    scene_->groups.push_back(g);
  }
  geometry::set_normals_from_faces(*scene_, first_vertex,
                                   static_cast<std::uint32_t>(scene_->positions.size()) - first_vertex, first_index,
                                   static_cast<std::uint32_t>(scene_->indices.size()) - first_index);
}

}  // namespace sylva::turtle
