#include "render/vector_drawing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <utility>

#include "render/gl_meshes.h"

namespace sylva::io {

namespace {

using geometry::Camera;
using geometry::Vec2;
using geometry::Vec3;

constexpr int kCircleSides = 48;  // polygons for circles seen at an angle
constexpr int kCapSides = 24;     // per end of a tapered round-capped segment

Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator*(Vec2 a, float k) { return {a.x * k, a.y * k}; }
float cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// Andrew's monotone chain; counter-clockwise, no repeated end point.
std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Two unit vectors spanning the plane perpendicular to `n` (unit).
std::pair<Vec3, Vec3> plane_basis(Vec3 n) {
  Vec3 axis = std::fabs(n.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 a = geometry::normalized(geometry::cross(n, axis));
  return {a, geometry::cross(n, a)};
}

class Projector {
 public:
  Projector(const geometry::Scene& scene, const geometry::Palette& palette, const Camera& camera,
            geometry::LineStyle line_style, LineCap cap, std::vector<Shape>& out)
      : scene_(scene), palette_(palette), camera_(camera), line_style_(line_style), cap_(cap), out_(out) {}

  void segment(const geometry::Segment& s);
  void circle(const geometry::Circle& c);
  void sphere(const geometry::Sphere& s);
  void label(const geometry::Label& l);
  void group(const geometry::TriangleGroup& g);

 private:
  Vec2 at(Vec3 p) const {
    Vec3 q = camera_.to_pixels(p);
    return {q.x, q.y};
  }
  // Primitives wholly outside the clipping planes are dropped; in perspective
  // so is anything reaching in front of the near plane, which cannot be
  // projected. The rest is drawn whole.
  bool in_view(const Vec3* p, std::size_t n) const {
    bool all_near = true, all_far = true;
    for (std::size_t i = 0; i < n; ++i) {
      float d = camera_.view_distance(p[i]);
      if (camera_.perspective() && d < camera_.near_plane()) return false;
      all_near = all_near && d < camera_.near_plane();
      all_far = all_far && d > camera_.far_plane();
    }
    return !all_near && !all_far;
  }
  // A width of 0 still draws, as the thinnest line.
  float pixels(float width, Vec3 where) const { return width > 0 ? width * camera_.pixels_per_unit_at(where) : 1; }
  Shape& add(Shape::Kind kind, int color, geometry::Provenance from, float depth) {
    Shape& s = out_.emplace_back();
    s.kind = kind;
    s.color = palette_.color(color);
    if (palette_.from_materials) s.opacity = std::clamp(1 - palette_.at(color).transparency, 0.0f, 1.0f);
    s.from = from;
    s.depth = depth;
    return s;
  }
  void tapered(const geometry::Segment& s, float depth, Vec2 a, Vec2 b, float wa, float wb);
  bool outline(const geometry::TriangleGroup& g);

  const geometry::Scene& scene_;
  const geometry::Palette& palette_;
  const Camera& camera_;
  geometry::LineStyle line_style_;
  LineCap cap_;
  std::vector<Shape>& out_;
};

void Projector::segment(const geometry::Segment& s) {
  const Vec3 ends[2] = {s.start, s.end};
  if (!in_view(ends, 2)) return;
  const float depth = camera_.view_distance((s.start + s.end) * 0.5f);
  if (line_style_ == geometry::LineStyle::Polygon) {
    Vec3 side = geometry::cross(s.up, s.end - s.start);
    if (geometry::length(side) > 0) {
      // The flat strip lies in the plane of heading and left, facing up.
      side = geometry::normalized(side);
      Shape& q = add(Shape::Kind::Polygon, s.color, s.from, depth);
      q.points = {at(s.start + side * (s.start_width * 0.5f)), at(s.end + side * (s.end_width * 0.5f)),
                  at(s.end - side * (s.end_width * 0.5f)), at(s.start - side * (s.start_width * 0.5f))};
      return;
    }
    // No length or no up to orient a strip by: drawn as a line instead.
  }
  Vec2 a = at(s.start), b = at(s.end);
  if (line_style_ == geometry::LineStyle::Pixel) {
    // As lpfg's glLineWidth, and the PNG renderer: the turtle's width in pixels, one per line.
    Shape& line = add(Shape::Kind::Line, s.color, s.from, depth);
    line.points = {a, b};
    line.stroke = std::max(1.0f, s.start_width);
    return;
  }
  float wa = pixels(s.start_width, s.start), wb = pixels(s.end_width, s.end);
  if (std::fabs(wa - wb) <= 1e-3f * std::max(wa, wb)) {
    Shape& line = add(Shape::Kind::Line, s.color, s.from, depth);
    line.points = {a, b};
    line.stroke = (wa + wb) * 0.5f;
    return;
  }
  tapered(s, depth, a, b, wa, wb);
}

// A segment whose width changes along it has no line to draw it with: it is
// the polygon a line with those end widths and caps would cover.
void Projector::tapered(const geometry::Segment& s, float depth, Vec2 a, Vec2 b, float wa, float wb) {
  std::vector<Vec2> points;
  if (cap_ == LineCap::Round) {
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < kCapSides; ++i) {
        float t = 2 * std::numbers::pi_v<float> * static_cast<float>(i) / kCapSides;
        float r = (end ? wb : wa) * 0.5f;
        points.push_back((end ? b : a) + Vec2{std::cos(t), std::sin(t)} * r);
      }
    points = convex_hull(std::move(points));
  } else {
    Vec2 d = b - a;
    float len = std::hypot(d.x, d.y);
    if (len == 0) return;
    d = d * (1 / len);
    Vec2 n{-d.y, d.x};
    if (cap_ == LineCap::Square) a = a - d * (wa * 0.5f), b = b + d * (wb * 0.5f);
    points = {a + n * (wa * 0.5f), b + n * (wb * 0.5f), b - n * (wb * 0.5f), a - n * (wa * 0.5f)};
  }
  add(Shape::Kind::Polygon, s.color, s.from, depth).points = std::move(points);
}

void Projector::circle(const geometry::Circle& c) {
  if (!in_view(&c.center, 1)) return;
  const float ppu = camera_.pixels_per_unit_at(c.center);
  const float depth = camera_.view_distance(c.center);
  const float stroke = c.outline > 0 ? c.outline * ppu : 0;
  const Vec3 n = geometry::normalized(c.normal);
  const bool face_on = c.facing_viewer || geometry::length(n) == 0 ||
                       (!camera_.perspective() && std::fabs(geometry::dot(n, camera_.direction())) > 0.99999f);
  if (face_on) {
    Shape& disc = add(Shape::Kind::Circle, c.color, c.from, depth);
    disc.points = {at(c.center)};
    disc.radius = c.radius * ppu;
    disc.stroke = stroke;
    return;
  }
  // Seen at an angle the circle is an ellipse (in perspective, nearly one):
  // its projected points make the polygon.
  auto [u, v] = plane_basis(n);
  Shape& ring = add(Shape::Kind::Polygon, c.color, c.from, depth);
  ring.stroke = stroke;
  for (int i = 0; i < kCircleSides; ++i) {
    float t = 2 * std::numbers::pi_v<float> * static_cast<float>(i) / kCircleSides;
    ring.points.push_back(at(c.center + (u * std::cos(t) + v * std::sin(t)) * c.radius));
  }
}

void Projector::sphere(const geometry::Sphere& s) {
  if (!in_view(&s.center, 1)) return;
  Shape& disc = add(Shape::Kind::Circle, s.color, s.from, camera_.view_distance(s.center));
  disc.points = {at(s.center)};
  disc.radius = s.radius * camera_.pixels_per_unit_at(s.center);
}

void Projector::label(const geometry::Label& l) {
  if (l.text.empty() || !in_view(&l.position, 1)) return;
  Shape& text = add(Shape::Kind::Text, l.color, l.from, camera_.view_distance(l.position));
  text.points = {at(l.position)};
  text.text = l.text;
}

void Projector::group(const geometry::TriangleGroup& g) {
  using Kind = geometry::TriangleGroup::Kind;
  if ((g.kind == Kind::Polygon || g.kind == Kind::Rhombus || g.kind == Kind::Triangle) && outline(g)) return;
  for (std::uint32_t k = 0; k + 2 < g.index_count; k += 3) {
    const std::uint32_t* idx = &scene_.indices[g.first_index + k];
    const Vec3 p[3] = {scene_.positions[idx[0]], scene_.positions[idx[1]], scene_.positions[idx[2]]};
    if (!in_view(p, 3)) continue;
    Vec2 q[3] = {at(p[0]), at(p[1]), at(p[2])};
    if (std::fabs(cross2(q[1] - q[0], q[2] - q[0])) < 1e-6f) continue;  // seen edge-on
    Shape& t = add(Shape::Kind::Polygon, g.color, g.from, camera_.view_distance((p[0] + p[1] + p[2]) / 3));
    t.points = {q[0], q[1], q[2]};
    t.hide_seams = t.opacity >= 1;  // overlapping outlines would show through a translucent surface
  }
}

// A flat group (a polygon the turtle triangulated) drawn as its outline: one
// shape per polygon, and no seams between its triangles. Vertices are matched
// by position, since a group may repeat a vertex for each triangle. False when
// the triangles do not make a simple boundary (closed, or edges shared by
// three triangles); the group is then drawn triangle by triangle.
bool Projector::outline(const geometry::TriangleGroup& g) {
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> ids;
  std::vector<Vec3> vertices;
  auto id_of = [&](Vec3 p) {
    std::array<std::uint32_t, 3> key;
    std::memcpy(key.data(), &p, sizeof key);
    auto [it, fresh] = ids.emplace(key, static_cast<std::uint32_t>(vertices.size()));
    if (fresh) vertices.push_back(p);
    return it->second;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::uint32_t k = 0; k + 2 < g.index_count; k += 3) {
    std::uint32_t v[3];
    for (int i = 0; i < 3; ++i) v[i] = id_of(scene_.positions[scene_.indices[g.first_index + k + i]]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    for (int i = 0; i < 3; ++i) ++edges[std::minmax(v[i], v[(i + 1) % 3])];
  }
  std::vector<std::vector<std::uint32_t>> neighbours(vertices.size());
  for (const auto& [edge, count] : edges) {
    if (count != 1) continue;
    neighbours[edge.first].push_back(edge.second);
    neighbours[edge.second].push_back(edge.first);
  }
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<bool> done(vertices.size(), false);
  for (std::uint32_t start = 0; start < vertices.size(); ++start) {
    if (neighbours[start].empty() || done[start]) continue;
    std::vector<std::uint32_t>& loop = loops.emplace_back();
    std::uint32_t previous = start, current = start;
    do {
      if (neighbours[current].size() != 2 || done[current]) return false;
      done[current] = true;
      loop.push_back(current);
      const auto& next = neighbours[current];
      std::uint32_t following = next[0] != previous ? next[0] : next[1];
      previous = current, current = following;
    } while (current != start);
    if (loop.size() < 3) return false;
  }
  if (loops.empty()) return false;
  if (!in_view(vertices.data(), vertices.size())) return true;

  float depth = 0;
  for (Vec3 p : vertices) depth += camera_.view_distance(p);
  Shape& shape = add(Shape::Kind::Polygon, g.color, g.from, depth / static_cast<float>(vertices.size()));
  for (const auto& loop : loops) {
    for (std::uint32_t v : loop) shape.points.push_back(at(vertices[v]));
    if (loops.size() > 1) shape.loop_ends.push_back(static_cast<std::uint32_t>(shape.points.size()));
  }
  return true;
}

}  // namespace

Drawing project_scene(const geometry::Scene& scene, const geometry::Palette& palette,
                      const geometry::ViewParameters& view, geometry::LineStyle line_style, int width, int height,
                      LineCap line_cap) {
  // Framed as the PNG renderer frames it, so a drawing and an image of a model match.
  const Camera camera(view, gl::drawn_bounds(scene, line_style), width, height);
  Drawing drawing;
  drawing.width = camera.width();
  drawing.height = camera.height();
  drawing.background = palette.background();
  drawing.line_cap = line_cap;

  Projector projector(scene, palette, camera, line_style, drawing.line_cap, drawing.shapes);
  for (const auto& s : scene.segments) projector.segment(s);
  for (const auto& c : scene.circles) projector.circle(c);
  for (const auto& s : scene.spheres) projector.sphere(s);
  for (const auto& g : scene.groups) projector.group(g);
  for (const auto& l : scene.labels) projector.label(l);

  // Painter's algorithm, far to near. Depths closer than a hundred-thousandth
  // of the view's depth count as equal, and then the string's order decides
  // (later modules over earlier, as lpfg draws a flat model).
  const double step = std::max(static_cast<double>(camera.far_plane() - camera.near_plane()), 1e-30) * 1e-5;
  std::vector<std::pair<long long, std::size_t>> order;
  order.reserve(drawing.shapes.size());
  for (std::size_t i = 0; i < drawing.shapes.size(); ++i)
    order.emplace_back(static_cast<long long>(std::clamp(std::floor(drawing.shapes[i].depth / step), -1e15, 1e15)), i);
  std::stable_sort(order.begin(), order.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    return drawing.shapes[a.second].from.module_index < drawing.shapes[b.second].from.module_index;
  });
  std::vector<Shape> sorted;
  sorted.reserve(drawing.shapes.size());
  for (const auto& entry : order) sorted.push_back(std::move(drawing.shapes[entry.second]));
  drawing.shapes = std::move(sorted);
  return drawing;
}

}  // namespace sylva::io
