#include "io/function_file.h"

#include "io/input_text.h"

namespace sylva::io {

namespace {

// The function editor's B-splines are cubic: fewer control points define no curve.
constexpr int kMinimumPoints = 4;

geometry::Function read_funcedit(WordReader& in, const std::string& default_name) {
  geometry::Function function;
  function.name = default_name;
  if (in.accept("fver")) {
    in.integer("the major version");
    in.integer("the minor version");
  }
  bool have_points = false;
  while (!in.at_end()) {
    std::string key = to_lower(in.peek().text);
    if (key == "fver" || key == "funcgalleryver") break;
    // Version 1.0 files start with "range:"; in a set it begins the next function.
    if (key == "range:" && have_points) break;
    Word key_word = in.next("a key");
    if (key == "name:") {
      function.name = in.rest_of_line("the function's name");
    } else if (key == "samples:") {
      Word samples_word = in.peek();
      function.samples = in.integer("the number of samples");
      if (function.samples < 1)
        in.fail(samples_word, "expected a positive number of samples, found '" + samples_word.text + "'");
    } else if (key == "flip:") {
      Word flag = in.next("on or off");
      if (!parse_flag(flag.text)) in.fail(flag, "expected on or off, found '" + flag.text + "'");
    } else if (key == "range:") {
      in.number("the start of the range");
      in.number("the end of the range");
    } else if (skip_editor_background(in, key)) {
    } else if (key == "points:") {
      if (have_points) in.fail(key_word, "the points are given twice");
      have_points = true;
      Word count_word = in.peek();
      int count = in.integer("the number of control points");
      if (count < kMinimumPoints)
        in.fail(count_word, "expected at least 4 control points, found " + count_word.text);
      for (int i = 0; i < count; ++i) {
        std::string what = "control point " + std::to_string(i + 1) + " of " + std::to_string(count);
        Word x_word = in.peek();
        geometry::Vec2 p;
        p.x = in.number(what + " (x)");
        p.y = in.number(what + " (y)");
        // A third number on the point's line repeats the point (funcedit's
        // multiplicity; lpfg and cpfg read it).
        int multiplicity = 1;
        if (in.next_is_number() && in.peek().line == x_word.line) {
          Word m_word = in.peek();
          multiplicity = in.integer("the multiplicity of " + what);
          if (multiplicity < 1) in.fail(m_word, "expected a multiplicity of 1 or more, found '" + m_word.text + "'");
        }
        if (!function.points.empty() && p.x < function.points.back().x)
          in.fail(x_word, "expected x of " + what + " to be at least the previous point's x (" +
                              std::to_string(function.points.back().x) + "), found '" + x_word.text + "'");
        function.points.insert(function.points.end(), static_cast<std::size_t>(multiplicity), p);
      }
    } else {
      in.fail(key_word, "expected a function key (name:, samples:, flip:, points:), found '" + key_word.text + "'");
    }
  }
  if (!have_points) in.expected("'points:'");
  return function;
}

}  // namespace

geometry::Function read_function_file(const std::string& path) {
  WordReader in(path, read_input_file(path, "function file"));
  geometry::Function function = read_funcedit(in, stem_of(path));
  if (!in.at_end()) in.expected("the end of the function");
  return function;
}

std::vector<geometry::Function> read_function_set_file(const std::string& path) {
  return read_gallery<geometry::Function>(path, "func", "function", read_funcedit);
}

}  // namespace sylva::io
