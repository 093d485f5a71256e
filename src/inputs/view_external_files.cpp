// The files a view file names, relative to its folder: surfaces and meshes
// (LPFG manual 8.1.5), and cpfg's surfaces with their ids, contours,
// functions, function sets and curves (CPFG manual 8.1.5, 8.1.6). The files
// themselves are read by read_input_files.
#include "inputs/view_parser.h"

namespace sylva::io {

namespace {

// A file name's word, kept with where it stands for messages about the file.
template <class C>
void name_file(C& command, const Word& at, const std::string& view_path) {
  command.file = at.text;
  command.path = resolve_beside(view_path, at.text);
  command.line = at.line;
  command.column = at.column;
}

}  // namespace

// lpfg: "surface: file.s [scale [sdiv tdiv [texture]]]"; cpfg: "surface: id
// file.s scale [sdiv tdiv] [texture]", the id the letter ~id draws it by
// and the scale 1 where it is not positive.
void Parser::surface(WordReader& in) {
  SurfaceCommand s;
  if (cpfg()) {
    Word id = in.next("a surface id");
    s.id = id.text.substr(0, 1);
    for (const SurfaceCommand& other : view_.surfaces)
      if (other.id == s.id) in.fail(id, "a second surface with id '" + s.id + "'");
  }
  Word at = in.next("a surface file name");
  name_file(s, at, view_.path);
  if (cpfg()) {
    const float scale = in.number("the surface scale");
    s.scale = scale > 0 ? scale : 1;
    std::vector<int> numbers;
    while (numbers.size() < 3 && in.next_is_number()) numbers.push_back(in.integer_at_most("a number of subdivisions or a texture id", kMaxSubdivisions));
    if (numbers.size() == 1) s.texture = numbers[0];
    if (numbers.size() >= 2) s.s_divisions = numbers[0], s.t_divisions = numbers[1];
    if (numbers.size() == 3) s.texture = numbers[2];
    // Its texture goes after the texture: commands' (which @Tx numbers).
    if (!in.at_end()) s.texture_path = resolve_beside(view_.path, in.next("a texture file").text);
  } else {
    if (!in.at_end()) s.scale = positive(in, "the surface scale");
    if (!in.at_end()) {
      Word sw = in.peek();
      s.s_divisions = in.integer_at_most("the subdivisions along s", kMaxSubdivisions);
      s.t_divisions = in.integer_at_most("the subdivisions along t (sdiv and tdiv go together)", kMaxSubdivisions);
      if (s.s_divisions < 1 || s.t_divisions < 1) in.fail(sw, "expected positive numbers of subdivisions");
    }
    if (!in.at_end()) {
      Word tw = in.peek();
      s.texture = in.integer("the texture id");
      if (s.texture < 0) in.fail(tw, "expected a texture id of 0 or more, found '" + tw.text + "'");
    }
  }
  view_.surfaces.push_back(s);
}

// lpfg: "texture: file" (ids from 0, LPFG manual 8.1.5); cpfg: subcommands
// "texture: F: file E: mode S: R: ratio H: filter L: filter" (ids from 1 in
// @Tx, CPFG manual 8.1.7). Only the file is used; the other subcommands are
// read and said to be ignored.
void Parser::texture(WordReader& in) {
  const Word first = in.next("an image file name or F:");
  if (first.text.size() < 2 || first.text.back() != ':') {
    view_.textures.push_back(resolve_beside(view_.path, first.text));
    return;
  }
  std::string file;
  for (Word key = first;; key = in.next("a texture subcommand")) {
    const std::string k = to_lower(key.text);
    if (k == "f:") {
      file = in.next("a texture file name").text;
    } else if (k == "s:") {
      warn(key, "texture subcommand S: (one texture per surface) ignored");
    } else if (k == "e:" || k == "r:" || k == "h:" || k == "l:") {
      const Word value = in.next("the value of " + key.text);
      if (k == "e:" || k == "r:") warn(key, "texture subcommand " + key.text + " " + value.text + " ignored");
    } else {
      in.fail(key, "expected a texture subcommand (F:, E:, S:, R:, H: or L:), found '" + key.text + "'");
    }
    if (in.at_end()) break;
  }
  if (file.empty()) in.fail(first, "a cpfg texture needs its file (F: file)");
  view_.textures.push_back(resolve_beside(view_.path, file));
}

// cpfg's "background scene: file" (CPFG manual 8.1.4, 8.3); cpfg splits the
// rest of the line into several files at blanks, commas and semicolons.
void Parser::background_scene(WordReader& in) {
  const std::string names = in.rest_of_line("a background scene file");
  std::string name;
  for (char c : names + " ") {
    if (c == ' ' || c == '\t' || c == ',' || c == ';') {
      if (!name.empty()) view_.background_scenes.push_back(resolve_beside(view_.path, name));
      name.clear();
    } else {
      name += c;
    }
  }
}

void Parser::mesh(WordReader& in) {
  MeshCommand m;
  m.file = in.next("a mesh file name").text;
  m.path = resolve_beside(view_.path, m.file);
  while (!in.at_end()) {
    Word key = in.next("a mesh part");
    std::string k = to_lower(key.text);
    if (k == "s:") {
      m.scale = positive(in, "the mesh scale");
    } else if (k == "c:") {
      m.contact = in.vec3("the contact point");
    } else {
      in.fail(key, "expected S: or C:, found '" + key.text + "'");
    }
  }
  view_.meshes.push_back(m);
}

// cpfg's "contour: id file": the contour @#(id) and generalized cylinders use.
void Parser::contour(WordReader& in) {
  ContourCommand c;
  Word id = in.peek();
  c.id = in.integer_at_most("the contour id", kMaxInputId);
  if (c.id < 1) in.fail(id, "expected a contour id of 1 or more (0 is cpfg's circle), found '" + id.text + "'");
  name_file(c, in.next("a contour file name"), view_.path);
  view_.contour_files.push_back(c);
}

// cpfg's "function: file [samples]": func(id, x)'s function, ids from 1 in
// the order of these commands.
void Parser::function(WordReader& in) {
  FunctionCommand f;
  name_file(f, in.next("a function file name"), view_.path);
  if (in.next_is_number()) f.samples = in.integer_at_most("the number of samples", kMaxSamples);
  view_.function_files.push_back(f);
}

// cpfg's "function set: file.fset": replaces the functions given before it.
void Parser::function_set(WordReader& in) {
  FunctionCommand f;
  f.set = true;
  name_file(f, in.next("a function set file name"), view_.path);
  view_.function_files.push_back(f);
}

// cpfg's "curve: file [samples]": the curves of curveX, curveY, curveZ and
// curveGAL, ids from 1 in the order of these commands.
void Parser::curve(WordReader& in) {
  FunctionCommand c;
  name_file(c, in.next("a curve file name"), view_.path);
  c.samples = 100;  // cpfg's default
  if (in.next_is_number()) c.samples = in.integer_at_most("the number of samples", kMaxSamples);
  view_.curve_files.push_back(c);
}

}  // namespace sylva::io
