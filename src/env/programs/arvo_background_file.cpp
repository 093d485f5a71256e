#include "env/programs/arvo_background_file.h"

#include <cctype>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "env/keyword.h"
#include "env/programs/parameter_file.h"
#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::env::arvo {
namespace {

struct Token {
  std::string text;
  int line = 0;
  int column = 0;
};

// Words of the file without comments, macros replaced by their values; the
// last token is an empty one where the file ends.
std::vector<Token> tokenize(const std::string& file, const std::string& text) {
  std::vector<Token> tokens;
  std::map<std::string, std::vector<std::string>> macros;
  int line = 1, column = 1;
  std::size_t i = 0;
  bool line_start = true;
  auto advance = [&](std::size_t count) {
    for (std::size_t k = 0; k < count && i < text.size(); ++k, ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
        line_start = true;
      } else {
        ++column;
      }
    }
  };
  while (i < text.size()) {
    char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      advance(1);
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      int at_line = line, at_column = column;
      std::size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) throw ModelError(SourceLocation{file, at_line, at_column}, "comment not closed: expected '*/'");
      bool was_start = line_start;
      advance(end + 2 - i);
      line_start = was_start && line_start;
      continue;
    }
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') advance(1);
      continue;
    }
    if (c == '#' && line_start) {
      int at_line = line, at_column = column;
      std::size_t end = text.find('\n', i);
      std::string directive = text.substr(i, end == std::string::npos ? std::string::npos : end - i);
      std::istringstream words(directive.substr(1));
      std::string keyword, name, value;
      words >> keyword >> name;
      if (keyword != "define" || name.empty() || name.find('(') != std::string::npos)
        throw ModelError(SourceLocation{file, at_line, at_column},
                         "expected '#define NAME value'; other preprocessor directives are not understood here");
      std::vector<std::string> values;
      while (words >> value) {
        if (value.rfind("/*", 0) == 0 || value.rfind("//", 0) == 0) break;
        values.push_back(value);
      }
      macros[name] = values;
      while (i < text.size() && text[i] != '\n') advance(1);
      continue;
    }
    line_start = false;
    std::size_t end = i;
    while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) && text.compare(end, 2, "/*") != 0 &&
           text.compare(end, 2, "//") != 0)
      ++end;
    Token token{text.substr(i, end - i), line, column};
    auto macro = macros.find(token.text);
    if (macro != macros.end()) {
      for (const std::string& value : macro->second) tokens.push_back({value, token.line, token.column});
    } else {
      tokens.push_back(token);
    }
    advance(end - i);
  }
  tokens.push_back({"", line, column});
  return tokens;
}

std::optional<double> to_number(std::string_view text) { return parse_number<double>(text); }

class BackgroundReader {
 public:
  BackgroundReader(std::string file, std::vector<Token> tokens, ObstacleScene& scene)
      : file_(std::move(file)), tokens_(std::move(tokens)), scene_(scene) {}

  void read() {
    while (!at_end()) command();
  }

 private:
  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    throw ModelError(SourceLocation{file_, at.line, at.column}, message);
  }

  bool at_end() const { return next_ + 1 >= tokens_.size(); }
  bool next_is_number() const { return !at_end() && to_number(tokens_[next_].text).has_value(); }

  double number(const std::string& command, const std::string& what) {
    if (at_end()) fail(tokens_.back(), "expected " + what + " for '" + command + "', found the end of the file");
    const Token& token = tokens_[next_];
    auto value = to_number(token.text);
    if (!value) fail(token, "expected " + what + " for '" + command + "', found '" + token.text + "'");
    ++next_;
    return *value;
  }

  std::vector<double> numbers(const std::string& command, int count, const std::string& what) {
    std::vector<double> values;
    for (int i = 0; i < count; ++i) values.push_back(number(command, what));
    return values;
  }

  // All numbers up to the next command.
  std::vector<double> number_list() {
    std::vector<double> values;
    while (next_is_number()) values.push_back(*to_number(tokens_[next_++].text));
    return values;
  }

  Vec3 point(const Vec3& local) const { return matrix_.point(local); }

  void polygon(const std::vector<Vec3>& corners) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) scene_.add_triangle(corners[0], corners[k], corners[k + 1]);
  }

  std::vector<Vec3> vertices(const Token& at, const std::string& command, int stride, std::size_t least) {
    std::vector<double> values = number_list();
    if (values.size() % stride != 0 || values.size() / stride < least)
      fail(at, "expected at least " + std::to_string(least) + " vertices of " + std::to_string(stride) +
                   " numbers each after '" + command + "', found " + std::to_string(values.size()) + " numbers");
    std::vector<Vec3> corners;
    for (std::size_t k = 0; k < values.size(); k += stride) corners.push_back(point({values[k], values[k + 1], values[k + 2]}));
    return corners;
  }

  void command() {
    const Token& at = tokens_[next_++];
    const std::string name = lowercase(at.text);
    if (name == "polygon") {
      polygon(vertices(at, name, 3, 3));
    } else if (name == "polygonuv") {
      polygon(vertices(at, name, 6, 3));
    } else if (name == "mesh") {
      std::vector<Vec3> v = vertices(at, name, 3, 4);
      if (v.size() % 2 != 0) fail(at, "expected an even number of vertices (4 + 2k) after 'mesh'");
      // Rectangle k has vertices 2k .. 2k+3; both diagonals are used so that
      // the rectangle is covered whichever way round its corners go.
      for (std::size_t k = 0; k + 3 < v.size(); k += 2) {
        scene_.add_triangle(v[k], v[k + 1], v[k + 2]);
        scene_.add_triangle(v[k + 1], v[k + 2], v[k + 3]);
        scene_.add_triangle(v[k], v[k + 1], v[k + 3]);
        scene_.add_triangle(v[k], v[k + 2], v[k + 3]);
      }
    } else if (name == "rectangle") {
      auto s = numbers(name, 2, "a side length");
      polygon({point({0, 0, 0}), point({s[0], 0, 0}), point({s[0], s[1], 0}), point({0, s[1], 0})});
    } else if (name == "box") {
      auto s = numbers(name, 3, "an edge length");
      box(s[0], s[1], s[2]);
    } else if (name == "cone") {
      auto s = numbers(name, 3, "a number (r1 r2 h)");
      scene_.add_frustum(matrix_, s[0], s[1], s[2]);
    } else if (name == "cylinder") {
      auto s = numbers(name, 2, "a number (r h)");
      scene_.add_frustum(matrix_, s[0], s[0], s[1]);
    } else if (name == "sphere") {
      scene_.add_sphere(matrix_, number(name, "a radius"));
    } else if (name == "material") {
      numbers(name, 17, "a material value (17 numbers)");
    } else if (name == "loadidentity") {
      matrix_ = Mat4{};
    } else if (name == "loadmatrix" || name == "mulmatrix") {
      auto values = numbers(name, 16, "a matrix entry (16 numbers, column by column)");
      Mat4 m;
      for (int k = 0; k < 16; ++k) m.m[k] = values[k];
      matrix_ = name == "loadmatrix" ? m : matrix_ * m;
    } else if (name == "pushmatrix") {
      stack_.push_back(matrix_);
    } else if (name == "popmatrix") {
      if (stack_.empty()) fail(at, "'popmatrix' without a matching 'pushmatrix'");
      matrix_ = stack_.back();
      stack_.pop_back();
    } else if (name == "translate") {
      auto t = numbers(name, 3, "a number (tx ty tz)");
      matrix_ = matrix_ * translation({t[0], t[1], t[2]});
    } else if (name == "rotate") {
      auto r = numbers(name, 4, "a number (angle vx vy vz)");
      matrix_ = matrix_ * rotation(r[0], {r[1], r[2], r[3]});
    } else if (name == "scale") {
      auto s = numbers(name, 3, "a number (sx sy sz)");
      matrix_ = matrix_ * scaling({s[0], s[1], s[2]});
    } else if (name == "clear") {
      numbers(name, 3, "a colour component");
    } else if (name == "light") {
      numbers(name, 4, "a coordinate (x y z w)");
    } else if (name == "ortho") {
      numbers(name, 6, "a number (minx maxx miny maxy front back)");
    } else if (name == "perspective") {
      numbers(name, 3, "a number (angle front back)");
    } else if (name == "lookat") {
      std::size_t count = number_list().size();
      if (count != 6 && count != 9) fail(at, "expected 6 or 9 numbers after 'lookat'");
    } else if (name == "matrixmode" || name == "maxtrixmode") {
      number(name, "a matrix mode (0 or 1)");
    } else {
      fail(at, "expected a background command (polygon, polygonuv, rectangle, mesh, box, cone, cylinder, sphere, "
               "material, loadidentity, loadmatrix, pushmatrix, popmatrix, translate, rotate, scale, mulmatrix), "
               "found '" + at.text + "'");
    }
  }

  void box(double a, double b, double c) {
    Vec3 v[8];
    for (int k = 0; k < 8; ++k) v[k] = point({k & 1 ? a : 0, k & 2 ? b : 0, k & 4 ? c : 0});
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& f : faces) polygon({v[f[0]], v[f[1]], v[f[2]], v[f[3]]});
  }

  std::string file_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  ObstacleScene& scene_;
  Mat4 matrix_;
  std::vector<Mat4> stack_;
};

}  // namespace

void read_background_file(const std::filesystem::path& path, ObstacleScene& scene) {
  const WholeFile file = read_whole_file(path.string());
  if (!file) throw ModelError(SourceLocation{path.string(), 0, 0}, "cannot open the arvo obstacles file");
  BackgroundReader(path.string(), tokenize(path.string(), file.bytes), scene).read();
}

}  // namespace sylva::env::arvo
