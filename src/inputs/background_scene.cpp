#include "inputs/background_scene.h"

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "inputs/input_text.h"
#include "support/default_compiler.h"

namespace sylva::io {

namespace {

using geometry::Vec3;

// Column-major 4 x 4, as OpenGL (and cpfg's matrix stack) keep them.
using Matrix = std::array<float, 16>;

constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      float sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[static_cast<std::size_t>(k * 4 + r)] * b[static_cast<std::size_t>(c * 4 + k)];
      m[static_cast<std::size_t>(c * 4 + r)] = sum;
    }
  return m;
}

Vec3 place(const Matrix& m, Vec3 p, float w = 1) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12] * w, m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13] * w,
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14] * w};
}

Matrix rotation(float degrees, Vec3 axis) {
  const Vec3 a = geometry::normalized(axis);
  const float r = degrees * std::numbers::pi_v<float> / 180, c = std::cos(r), s = std::sin(r), t = 1 - c;
  return {t * a.x * a.x + c,       t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0,
          t * a.x * a.y - s * a.z, t * a.y * a.y + c,       t * a.y * a.z + s * a.x, 0,
          t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c,       0,
          0,                       0,                       0,                       1};
}

struct SceneCommand {
  std::string keyword;
  std::vector<float> numbers;
  std::string file;
  int line = 0;
};

// Keywords and the numbers after each, across lines, as cpfg's fscanf reads them.
std::vector<SceneCommand> commands(const std::vector<PreprocessedLine>& lines) {
  std::vector<SceneCommand> out;
  for (const PreprocessedLine& line : lines) {
    std::istringstream words(line.text);
    std::string word;
    while (words >> word) {
      if (auto value = parse_float(word); value && !out.empty()) {
        out.back().numbers.push_back(*value);
        continue;
      }
      out.push_back({word, {}, line.file, line.line});
    }
  }
  return out;
}

class Builder {
 public:
  Builder(BackgroundScene& out, bool from_materials) : out_(out), from_materials_(from_materials) {}

  void run(const SceneCommand& c) {
    const auto& n = c.numbers;
    auto need = [&](std::size_t count) {
      if (n.size() >= count) return true;
      warn(c, "'" + c.keyword + "' needs at least " + std::to_string(count) + " numbers; skipped");
      return false;
    };
    const std::string& k = c.keyword;
    if (k == "material") material(n);
    else if (k == "pushmatrix") stack_.push_back(matrix_);
    else if (k == "popmatrix") {
      if (!stack_.empty()) matrix_ = stack_.back(), stack_.pop_back();
    } else if (k == "loadidentity") matrix_ = kIdentity;
    else if (k == "translate" && need(3)) matrix_ = multiply(matrix_, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, n[0], n[1], n[2], 1});
    else if (k == "rotate" && need(4)) matrix_ = multiply(matrix_, rotation(n[0], {n[1], n[2], n[3]}));
    else if (k == "scale" && need(3)) matrix_ = multiply(matrix_, {n[0], 0, 0, 0, 0, n[1], 0, 0, 0, 0, n[2], 0, 0, 0, 0, 1});
    else if ((k == "multmatrix" || k == "mulmatrix") && need(16)) matrix_ = multiply(matrix_, to_matrix(n));
    else if (k == "loadmatrix" && need(16)) matrix_ = to_matrix(n);
    else if (k == "polygon" && need(9)) polygon(n, false);
    else if (k == "polygonuv" && need(18)) polygon(n, true);
    else if (k == "rectangle" && need(2)) {
      const float x = n.size() >= 4 ? n[2] : 0, y = n.size() >= 4 ? n[3] : 0;
      rectangle({x, y, 0}, {x + n[0], y, 0}, {x + n[0], y + n[1], 0}, {x, y + n[1], 0});
    } else if (k == "mesh" && need(12)) {
      for (std::size_t j = 0; j + 12 <= n.size(); j += 6)
        rectangle(point(n, j), point(n, j + 6), point(n, j + 9), point(n, j + 3));
    } else if ((k == "box" || k == "prism") && need(3)) box(n[0], n[1], n[2]);
    else if (k == "sphere" && need(1)) sphere(n[0]);
    else if (k == "cylinder" && need(2)) tube(n[0], n[0], n[1]);
    else if (k == "cone" && need(3)) tube(n[0], n[1], n[2]);
    else if (k != "material" && k != "pushmatrix" && k != "popmatrix" && k != "loadidentity" && !known(k))
      warn(c, "unknown keyword '" + k + "' ignored");
  }

 private:
  static bool known(const std::string& k) {
    for (const char* name : {"translate", "rotate", "scale", "multmatrix", "mulmatrix", "loadmatrix", "polygon",
                             "polygonuv", "rectangle", "mesh", "box", "prism", "sphere", "cylinder", "cone"})
      if (k == name) return true;
    return false;
  }
  static Matrix to_matrix(const std::vector<float>& n) {
    Matrix m;
    for (std::size_t i = 0; i < 16; ++i) m[i] = n[i];
    return m;
  }
  static Vec3 point(const std::vector<float>& n, std::size_t at) { return {n[at], n[at + 1], n[at + 2]}; }

  void warn(const SceneCommand& c, const std::string& message) {
    out_.warnings.push_back(c.file + ":" + std::to_string(c.line) + ": warning: " + message);
  }

  // ambient, diffuse, specular, emission (RGBA each), shininess; the
  // diffuse alpha is the opacity. In colormap mode cpfg takes the diffuse
  // colour as the colormap entry.
  void material(const std::vector<float>& n) {
    geometry::Material m;
    auto rgb = [&](std::size_t at) { return geometry::Rgb{n[at], n[at + 1], n[at + 2]}; };
    if (n.size() >= 4) m.ambient = rgb(0);
    if (n.size() >= 8) m.diffuse = rgb(4), m.transparency = 1 - n[7];
    if (n.size() >= 12) m.specular = rgb(8);
    if (n.size() >= 16) m.emission = rgb(12);
    if (n.size() >= 17) m.shininess = n[16];
    if (!from_materials_) m.ambient = m.diffuse;
    color_ = background_color(static_cast<int>(out_.materials.size()));
    out_.materials.push_back(m);
  }

  void triangles(const std::vector<Vec3>& points, const std::vector<Vec3>& normals) {
    std::vector<std::uint32_t> fan;
    for (std::uint32_t k = 1; k + 1 < points.size(); ++k) fan.insert(fan.end(), {0, k, k + 1});
    out_.scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, points, normals, fan, color_, {});
  }

  // The normal from the first three points (cpfg: (p0 - p1) x (p2 - p1)).
  void polygon(const std::vector<float>& n, bool with_normals) {
    const std::size_t stride = with_normals ? 6 : 3;
    std::vector<Vec3> points, normals;
    for (std::size_t j = 0; j + 3 <= n.size(); j += stride) {
      points.push_back(place(matrix_, point(n, j)));
      if (with_normals && j + 6 <= n.size()) normals.push_back(geometry::normalized(place(matrix_, point(n, j + 3), 0)));
    }
    if (!with_normals) {
      const Vec3 p0 = point(n, 0), p1 = point(n, 3), p2 = point(n, 6);
      normals.assign(points.size(), geometry::normalized(place(matrix_, geometry::cross(p0 - p1, p2 - p1), 0)));
    }
    triangles(points, normals);
  }

  // cpfg's DrawRectangle: triangles (1, 2, 3) and (1, 3, 4), the normal
  // (p3 - p1) x (p2 - p1).
  void rectangle(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    const Vec3 normal = geometry::normalized(place(matrix_, geometry::cross(c - a, b - a), 0));
    const std::vector<Vec3> corners{place(matrix_, a), place(matrix_, b), place(matrix_, c), place(matrix_, d)};
    out_.scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, corners, std::vector<Vec3>(4, normal),
                             {0, 1, 2, 0, 2, 3}, color_, {});
  }

  void box(float a, float b, float c) {
    auto P = [&](int x, int y, int z) { return Vec3{static_cast<float>(x) * a, static_cast<float>(y) * b, static_cast<float>(z) * c}; };
    rectangle(P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0));
    rectangle(P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1));
    rectangle(P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0));
    rectangle(P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1));
    rectangle(P(0, 0, 0), P(0, 0, 1), P(1, 0, 1), P(1, 0, 0));
    rectangle(P(0, 1, 0), P(1, 1, 0), P(1, 1, 1), P(0, 1, 1));
  }

  // cpfg places the turtle's sphere at the transformed origin, unscaled.
  void sphere(float radius) {
    geometry::Sphere s;
    s.center = place(matrix_, {0, 0, 0});
    s.radius = radius;
    s.color = color_;
    out_.scene.spheres.push_back(s);
  }

  // A cylinder or cone along the local y axis, from radius r0 at the base to
  // r1 at height h, closed by discs (cpfg: StartNode, EndNode, Circle3D).
  void tube(float r0, float r1, float h) {
    const Vec3 base = place(matrix_, {0, 0, 0}), top = place(matrix_, {0, h, 0});
    geometry::Segment s;
    s.start = base;
    s.end = top;
    s.up = place(matrix_, {0, 0, -1}, 0);
    s.start_width = 2 * r0;
    s.end_width = 2 * r1;
    s.color = color_;
    out_.scene.segments.push_back(s);
    const std::pair<Vec3, float> ends[] = {{base, r0}, {top, r1}};
    for (const auto& [center, radius] : ends) {
      geometry::Circle disc;
      disc.center = center;
      disc.normal = place(matrix_, {0, 1, 0}, 0);
      disc.radius = radius;
      disc.color = color_;
      out_.scene.circles.push_back(disc);
    }
  }

  BackgroundScene& out_;
  bool from_materials_;
  Matrix matrix_ = kIdentity;
  std::vector<Matrix> stack_;
  int color_ = 0;
};

}  // namespace

BackgroundScene read_background_scene(const std::vector<std::string>& paths, const std::string& compiler,
                                      bool from_materials) {
  std::vector<PreprocessedLine> lines;
  for (const std::string& path : paths) {
    read_input_file(path, "background scene file");
    for (PreprocessedLine& line : preprocess_file(path, compiler_or_default(compiler)))
      lines.push_back(std::move(line));
  }
  return parse_background_scene(lines, from_materials);
}

BackgroundScene parse_background_scene(const std::vector<PreprocessedLine>& lines, bool from_materials) {
  BackgroundScene out;
  Builder builder(out, from_materials);
  for (const SceneCommand& c : commands(lines)) builder.run(c);
  return out;
}

}  // namespace sylva::io
