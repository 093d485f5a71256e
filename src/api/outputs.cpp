#include "api/outputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>

#include "api/provenance.h"
#include "export/mesh_writers.h"
#include "geometry/back_sides.h"
#include "geometry/tessellation.h"
#include "inputs/input_text.h"
#include "inputs/label_font.h"
#include "render/png_renderer.h"
#include "render/vector_writer.h"
#include "support/diagnostic.h"

namespace sylva {
namespace {

enum class Format { Obj, Ply, Glb, Vector, Png, Unknown };

Format format_of(const std::string& path) {
  const std::string ext = io::extension_of(path);
  if (ext == "obj") return Format::Obj;
  if (ext == "ply") return Format::Ply;
  if (ext == "glb") return Format::Glb;
  if (ext == "svg" || ext == "pdf" || ext == "ps" || ext == "eps") return Format::Vector;
  if (ext == "png") return Format::Png;
  return Format::Unknown;
}

// The view file's texture images; none for a cpfg model in colormap mode,
// where cpfg maps no textures (CPFG manual 6.7.4).
std::vector<io::TextureImage> texture_images(const io::ViewFile& view, const Simulation& s) {
  std::vector<io::TextureImage> images;
  if (s.types().cpfg() && !s.inputs().palette.from_materials) return images;
  for (const std::string& path : view.textures) images.push_back(io::read_texture_image(path));
  return images;
}

io::ImageSettings image_settings(const io::ViewFile& view, const Simulation& s) {
  io::ImageSettings settings;
  settings.render = view.render;
  settings.lights = view.lights_or_default();
  settings.contour_sides = view.contour_sides;
  settings.label_font = io::label_font(view, s.types().cpfg());
  settings.textures = texture_images(view, s);
  return settings;
}

void write_image(const std::string& path, const geometry::Scene& scene, const Simulation& s,
                 const geometry::ViewParameters& view, const OutputOptions& options) {
  io::write_png(path,
                io::render_image(scene, s.inputs().palette, view, image_settings(view_file_or_default(s), s),
                                 options.width, options.height),
                provenance_json(s));
}

geometry::TriangleMesh mesh_of(const geometry::Scene& scene, const geometry::TessellationOptions& tessellation) {
  geometry::TriangleMesh mesh = geometry::tessellate(scene, tessellation);
  geometry::split_back_sides(mesh);  // cpfg's back-side colours as parts of their own
  return mesh;
}

// The mesh files' mesh of a scene (cpfg's background included).
geometry::TriangleMesh export_mesh(const geometry::Scene& scene, const Simulation& simulation) {
  const io::ViewFile& view = view_file_or_default(simulation);
  // An L+C model's mesh is what lpfg exports (lines as cylinders of the
  // turtle's width whatever the line style); cpfg exports no meshes, so
  // a cpfg model's follows its view file.
  const geometry::TessellationOptions tessellation = simulation.types().cpfg()
                                                        ? view.tessellation_options()
                                                        : geometry::lpfg_export_options(view.contour_sides);
  return mesh_of(scene, tessellation);
}

// cpfg's background scene, drawn first, with the plant.
geometry::Scene with_background(const geometry::Scene& plant, const Simulation& simulation) {
  geometry::Scene scene = *simulation.inputs().background;
  scene.append(plant);
  return scene;
}

}  // namespace

const io::ViewFile& view_file_or_default(const Simulation& s) {
  static const io::ViewFile defaults;
  return s.inputs().view ? *s.inputs().view : defaults;
}

void check_output_path(const std::string& path) {
  if (format_of(path) == Format::Unknown)
    throw ModelError(SourceLocation{path, 0, 0},
                     "unknown output format (expected .obj, .ply, .glb, .svg, .pdf, .ps, .eps or .png)");
}

void write_output(const std::string& path, const geometry::Scene& plant, const Simulation& simulation,
                  const OutputOptions& options, int view_id) {
  check_output_path(path);
  geometry::Scene background_and_plant;
  if (simulation.inputs().background) background_and_plant = with_background(plant, simulation);
  const geometry::Scene& scene = simulation.inputs().background ? background_and_plant : plant;
  const io::ViewFile& view = view_file_or_default(simulation);
  const geometry::Palette& palette = simulation.inputs().palette;
  const Format f = format_of(path);
  const std::string provenance = provenance_json(simulation);  // "" without a ProvenanceScope
  switch (f) {
    case Format::Obj:
    case Format::Ply:
    case Format::Glb: {
      const geometry::TriangleMesh mesh = export_mesh(scene, simulation);
      if (f == Format::Obj) io::write_obj(path, mesh, palette, simulation.types(), provenance);
      else if (f == Format::Ply) io::write_ply(path, mesh, palette, simulation.types(), provenance);
      else io::write_glb(path, mesh, palette, simulation.types(), texture_images(view, simulation), provenance);
      break;
    }
    case Format::Vector:
      // Round caps join segments without notches; a view file may ask for lpfg's butt caps.
      io::write_vector_drawing(path, scene, palette, view.view(view_id), view.render.line_style, options.width,
                               options.height, &simulation.types(),
                               simulation.inputs().view ? view.render.ps_linecap : 1, provenance);
      break;
    case Format::Png:
      write_image(path, scene, simulation, view.view(view_id), options);
      break;
    case Format::Unknown:
      break;
  }
}

void check_frame_formats(const std::vector<std::string>& formats) {
  for (const std::string& format : formats)
    if (format != kStringFrame && format_of("frame." + format) == Format::Unknown)
      throw ModelError(SourceLocation{"--frame-format " + format, 0, 0},
                       "unknown frame format (expected png, obj, ply, glb, svg, pdf, ps, eps or str)");
}

void write_frame(const std::string& dir, int number, const std::vector<std::string>& formats, Simulation& simulation,
                 const geometry::ViewParameters& camera, const OutputOptions& options) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "frame-%04d.", number);
  const std::string path = (std::filesystem::path(dir) / stem).string();
  std::optional<geometry::Scene> scene;
  for (const std::string& format : formats) {
    if (format == kStringFrame) {
      write_recorded_string(path + format, simulation);  // and FILE.provenance.json, when recorded
      continue;
    }
    if (!scene) scene = simulation.scene();
    if (format == "png") write_image(path + format, *scene, simulation, camera, options);
    else write_output(path + format, *scene, simulation, options, simulation.primary_view());
  }
}

std::string scene_glb(const geometry::Scene& plant, const Simulation& simulation) {
  const io::ViewFile& view = view_file_or_default(simulation);
  const geometry::TriangleMesh mesh =
      mesh_of(simulation.inputs().background ? with_background(plant, simulation) : plant, view.tessellation_options());
  return io::encode_glb(mesh, simulation.inputs().palette, simulation.types(), texture_images(view, simulation));
}

int write_frames(const std::string& dir, Simulation& simulation, const OutputOptions& options, int steps,
                 const std::vector<std::string>& formats) {
  check_frame_formats(formats);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw ModelError(SourceLocation{dir, 0, 0}, "cannot create the frames folder: " + ec.message());

  const int length = steps >= 0 ? steps : simulation.derivation_length();
  const io::AnimationFile animation = simulation.inputs().animation.value_or(io::AnimationFile{});
  std::vector<int> frames = animation.frames(length);
  if (frames.empty()) return 0;

  const std::set<int> listed(frames.begin(), frames.end());
  const bool on_request = animation.display_on_request;
  // Which view is drawn is known once Start has run (UseView).
  geometry::ViewParameters view;
  auto choose_view = [&] { view = view_file_or_default(simulation).view(simulation.primary_view()); };
  if (!animation.scale_between_frames && !animation.new_view_between_frames) {
    // A first pass finds where the plant ends up, so the camera stays still.
    simulation.rewind();
    simulation.begin();
    choose_view();
    if (!view.box) {
      while (simulation.step_number() < frames.back() && simulation.step()) {
      }
      geometry::Box bounds = simulation.scene().bounds();
      if (!bounds.empty()) view.box = bounds;
    }
    simulation.finish();
  }
  const geometry::ViewParameters camera = view;

  int written = 0;
  simulation.rewind();
  simulation.begin();
  if (animation.scale_between_frames || animation.new_view_between_frames) choose_view();
  else view = camera;
  // The frame of step `done`: a listed one, or on request the first, the
  // last and those the model asked for with DisplayFrame().
  auto frame_wanted = [&](int done) {
    const bool asked = simulation.take_display_request();
    if (on_request) return done == frames.front() || done == frames.back() || (asked && done >= frames.front());
    return listed.count(done) > 0;
  };
  while (true) {
    const int done = simulation.step_number();
    const bool last = done >= frames.back() || simulation.stopped();
    if (frame_wanted(done) || (last && simulation.stopped())) {
      write_frame(dir, done, formats, simulation, view, options);
      ++written;
    }
    if (last) break;
    simulation.step();
  }
  simulation.finish();
  return written;
}

}  // namespace sylva
