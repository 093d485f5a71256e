#include "inputs/function_file.h"

#include "inputs/input_text.h"

namespace sylva::io {

namespace {

// The function editor's B-splines are cubic: fewer control points define no curve.
constexpr int kMinimumPoints = 4;

// Reads past the rest of the line `key` is on (a value that may be empty).
void skip_rest_of_line(WordReader& in, const Word& key) {
  while (!in.at_end() && in.peek().line == key.line) in.next("the rest of the line");
}

// "n" control points, one per line: x, y and an optional multiplicity (the
// point repeated, as lpfg and cpfg read it: a number, truncated).
void read_points(WordReader& in, geometry::Function& function) {
  Word count_word = in.peek();
  int count = in.integer_at_most("the number of control points", kMaxPoints);
  if (count < kMinimumPoints)
    in.fail(count_word, "expected at least 4 control points, found " + count_word.text);
  for (int i = 0; i < count; ++i) {
    std::string what = "control point " + std::to_string(i + 1) + " of " + std::to_string(count);
    Word x_word = in.peek();
    geometry::Vec2 p;
    p.x = in.number(what + " (x)");
    Word y_word = in.peek();
    p.y = in.number(what + " (y)");
    int multiplicity = 1;
    if (!in.at_end() && in.peek().line == y_word.line) {
      Word m_word = in.peek();
      const float m = in.number(what + " (its multiplicity)");
      if (!(m >= 0 && m < 1000))
        in.fail(m_word, "expected the multiplicity of " + what + " (a number of times, 0 to 999), found '" +
                            m_word.text + "'");
      multiplicity = static_cast<int>(m);
    }
    if (!function.points.empty() && p.x < function.points.back().x)
      in.fail(x_word, "expected x of " + what + " to be at least the previous point's x (" +
                          std::to_string(function.points.back().x) + "), found '" + x_word.text + "'");
    for (int k = 0; k < multiplicity; ++k) function.points.push_back(p);
  }
}

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
    if (key == "fver" || key == "funcgalleryver" || key == "timelinefunceditfileend:") break;
    // Version 1.0 files start with "range:"; in a set it begins the next function.
    if (key == "range:" && have_points) break;
    Word key_word = in.next("a key");
    if (key == "name:") {
      function.name = in.rest_of_line("the function's name");
    } else if (key == "samples:") {
      // lpfg keeps 10 to 1000 of them (LpfgFunction clamps), cpfg any number.
      function.samples = in.integer_at_most("the number of samples", kMaxSamples);
    } else if (key == "flip:") {
      Word flag = in.next("on or off");
      if (!parse_flag(flag.text)) in.fail(flag, "expected on or off, found '" + flag.text + "'");
    } else if (key == "range:") {
      in.number("the start of the range");
      in.number("the end of the range");
    } else if (key == "markers:") {
      // Marked points of the editor (cpfg reads past them): "mK x y" each.
      Word count_word = in.peek();
      int markers = in.integer_at_most("the number of markers", kMaxPoints);
      if (markers < 0) in.fail(count_word, "expected a number of markers, found '" + count_word.text + "'");
      for (int m = 0; m < markers; ++m) skip_rest_of_line(in, in.next("a marker"));
    } else if (skip_editor_background(in, key)) {
    } else if (key == "points:") {
      if (have_points) in.fail(key_word, "the points are given twice");
      have_points = true;
      read_points(in, function);
    } else {
      in.fail(key_word, "expected a function key (name:, samples:, flip:, points:), found '" + key_word.text + "'");
    }
  }
  if (!have_points) in.expected("'points:'");
  return function;
}

// One timeline of a .tset file.
geometry::Function read_timeline(WordReader& in, const std::string& default_name) {
  in.expect("start:");
  const float start = in.number("the timeline's start");
  in.expect("end:");
  const float end = in.number("the timeline's end");
  in.expect("name:");
  const std::string timeline_name = in.rest_of_line("the timeline's name");
  // The editor's colour and the endpoints' labels say nothing about the function.
  for (const char* key : {"color:", "startlabel:", "endlabel:"})
    if (to_lower(in.peek().text) == key) skip_rest_of_line(in, in.next(key));
  in.expect("timelineFunceditFileStart:");
  if (to_lower(in.peek().text) != "fver" && to_lower(in.peek().text) != "range:")
    in.expected("the timeline's function ('fver')");
  geometry::Function function = read_funcedit(in, timeline_name.empty() ? default_name : timeline_name);
  in.expect("timelineFunceditFileEnd:");
  function.low = start;
  function.up = end;
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

std::vector<geometry::Function> read_timeline_set_file(const std::string& path) {
  WordReader in(path, read_input_file(path, "timeline function set file"));
  in.expect("timeEdit");
  in.integer("the major version");
  in.integer("the minor version");
  in.expect("items:");
  Word count_word = in.peek();
  const int count = in.integer("the number of timelines");
  if (count < 0) in.fail(count_word, "expected a number of timelines, found '" + count_word.text + "'");
  std::vector<geometry::Function> functions;
  for (int i = 0; i < count; ++i) functions.push_back(read_timeline(in, stem_of(path) + "_" + std::to_string(i + 1)));
  if (!in.at_end()) in.expected("the end of the timelines (the file has " + std::to_string(count) + ")");
  return functions;
}

geometry::Function read_cpfg_function_file(const std::string& path, int view_samples) {
  const std::string text = read_input_file(path, "function file");
  WordReader in(path, text);
  const bool old_format = !in.at_end() && to_lower(in.peek().text) == "range:";
  geometry::Function function = read_funcedit(in, stem_of(path));
  if (!in.at_end()) in.expected("the end of the function");
  if (old_format) function.samples = view_samples;
  return function;
}

std::vector<geometry::Function> read_cpfg_function_set_file(const std::string& path) {
  return read_gallery<geometry::Function>(path, "func", "function", [](WordReader& in, const std::string& name) {
    const bool old_format = to_lower(in.peek().text) == "range:";
    geometry::Function function = read_funcedit(in, name);
    if (old_format) function.samples = 100;
    return function;
  });
}

}  // namespace sylva::io
