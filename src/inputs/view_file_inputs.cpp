#include "inputs/view_file_inputs.h"

#include "inputs/contour_file.h"
#include "inputs/curve_file.h"
#include "inputs/function_file.h"
#include "inputs/surface_file.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

// "file:line:column: warning: <what went wrong>; <what is done instead>", at
// the view file's word naming the file when the error is not inside it.
template <class C>
std::string warning(const ViewFile& view, const C& command, const ModelError& e, const std::string& instead) {
  const bool inside = e.where().line > 0;
  const std::string where = inside ? e.where().file + ":" + std::to_string(e.where().line) + ":" + std::to_string(e.where().column)
                                   : view.path + ":" + std::to_string(command.line) + ":" + std::to_string(command.column);
  return where + ": warning: " + e.message() + (inside ? "" : " " + command.path) + "; " + instead;
}

geometry::BezierSurface load_surface(const SurfaceCommand& command) {
  geometry::BezierSurface surface = read_surface_file(command.path);
  // Surface(id, s) scales by s * (view-file scale) / size.
  surface.size /= command.scale;
  surface.texture = command.texture;
  if (command.s_divisions > 0) {
    surface.u_divisions = command.s_divisions;
    surface.v_divisions = command.t_divisions;
  }
  return surface;
}

// Neither program keeps a surface it cannot read: later ones take its place.
void read_surfaces(InputFiles& inputs) {
  ViewFile& view = *inputs.view;
  std::vector<SurfaceCommand> kept;
  for (const SurfaceCommand& s : view.surfaces) {
    try {
      inputs.surfaces.push_back(load_surface(s));
      kept.push_back(s);
    } catch (const ModelError& e) {
      inputs.warnings.push_back(warning(view, s, e, "the surface is left out, as in lpfg and cpfg"));
    }
  }
  view.surfaces = std::move(kept);
}

// cpfg's contours at their ids; cpfg reads none from a contour it cannot
// read on.
void read_contours(InputFiles& inputs) {
  const ViewFile& view = *inputs.view;
  for (const ContourCommand& c : view.contour_files) {
    geometry::Contour contour;
    try {
      contour = read_contour_file(c.path);
    } catch (const ModelError& e) {
      inputs.warnings.push_back(warning(view, c, e, "cpfg reads no contour from this one on"));
      return;
    }
    const auto slot = static_cast<std::size_t>(c.id);
    if (inputs.contours.size() < slot) inputs.contours.resize(slot, geometry::Contour::circle());
    inputs.contours[slot - 1] = std::move(contour);
  }
}

// cpfg's functions in the order given, a function set replacing those before
// it; a function file it cannot read is 0 everywhere, keeping the ids after
// it. Only a function set's functions are named (cpfg defines their names
// for the model; the last command decides).
void read_functions(InputFiles& inputs) {
  const ViewFile& view = *inputs.view;
  std::vector<geometry::Function> functions;
  bool from_set = false;
  for (const FunctionCommand& f : view.function_files) {
    from_set = f.set;
    try {
      if (f.set) {
        functions = read_cpfg_function_set_file(f.path);
        continue;
      }
      // cpfg samples a file of the older format ("range:") as the view file
      // says; a newer one as it says itself.
      functions.push_back(read_cpfg_function_file(f.path, f.samples > 0 ? f.samples : -1));
    } catch (const ModelError& e) {
      if (f.set) {
        functions.clear();
        inputs.warnings.push_back(warning(view, f, e, "the set has no functions"));
      } else {
        geometry::Function zero;
        zero.points = {{0, 0}, {0, 0}, {0, 0}, {1, 0}};
        functions.push_back(std::move(zero));
        inputs.warnings.push_back(warning(view, f, e, "the function is 0 everywhere, as in cpfg"));
      }
    }
  }
  for (geometry::Function& f : functions) {
    if (!from_set) f.name.clear();
    inputs.functions.push_back(std::move(f));
  }
}

void read_curves(InputFiles& inputs) {
  const ViewFile& view = *inputs.view;
  for (const FunctionCommand& c : view.curve_files) {
    try {
      geometry::Contour curve = read_curve_file(c.path);
      // cpfg's table of arc lengths: the view file's count, 100 without one.
      curve.samples = c.samples > 0 ? c.samples : 100;
      inputs.curves.push_back(std::move(curve));
    } catch (const ModelError& e) {
      inputs.warnings.push_back(warning(view, c, e, "the curve is left out"));
    }
  }
}

}  // namespace

void read_view_file_inputs(InputFiles& inputs) {
  if (!inputs.view) return;
  read_surfaces(inputs);
  read_contours(inputs);
  read_functions(inputs);
  read_curves(inputs);
}

}  // namespace sylva::io
