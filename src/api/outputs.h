// Writing what a simulation shows: meshes (OBJ, PLY, glTF), vector drawings
// (SVG, PDF, PostScript), images (PNG) and animation frames, each chosen by
// its file extension.
#pragma once

#include <string>
#include <vector>

#include "api/simulation.h"
#include "geometry/camera.h"

namespace sylva {

// The model's view file, or lpfg's defaults when it has none.
const io::ViewFile& view_file_or_default(const Simulation& simulation);

// Throws ModelError naming `path` if its extension is not an output format.
void check_output_path(const std::string& path);

// Writes `scene` (the simulation's current string drawn by the turtle, from
// Simulation::scene(), computed once for all outputs) to `path`, seen by the
// camera of view `view` of the view file. While a ProvenanceScope of the
// simulation lives (api/provenance.h), every file written here, by
// write_frame and by write_frames carries its run record (a string frame in
// a sidecar FILE.provenance.json).
void write_output(const std::string& path, const geometry::Scene& scene, const Simulation& simulation,
                  const OutputOptions& options, int view = 0);

// `scene` as binary glTF (write_glb's layout, provenance included) drawn as
// the view file draws it: its line style (pixel lines as glTF lines) and
// contour sides, rather than as a mesh file exports it. What a viewer shows.
std::string scene_glb(const geometry::Scene& scene, const Simulation& simulation);

// What a frame can be written as: the output formats' extensions (png,
// obj, ply, glb, svg, pdf, ps, eps) and "str", the string's text.
inline constexpr const char* kStringFrame = "str";
// Throws ModelError naming a format that is none of those.
void check_frame_formats(const std::vector<std::string>& formats);

// The current state as DIR/frame-NNNN.EXT, N being `number`, in each of
// `formats`: PNG images seen by `camera` (one camera for a whole animation),
// the others as -o writes them.
void write_frame(const std::string& dir, int number, const std::vector<std::string>& formats, Simulation& simulation,
                 const geometry::ViewParameters& camera, const OutputOptions& options);

// Runs the derivation again from the axiom and writes one PNG (or the
// `formats` write_frame takes) per frame of the animation file (every step
// when there is none) into `dir` as frame-NNNN.png, N being the step. The
// camera frames the last frame's bounds unless the animation file asks to
// rescale between frames or the view file gives a box. With "display on
// request: on" the frames are the first, the last and the steps in which the
// model called DisplayFrame(). Frames show the simulation's primary view. Returns the number of frames written.
int write_frames(const std::string& dir, Simulation& simulation, const OutputOptions& options, int steps = -1,
                 const std::vector<std::string>& formats = {"png"});

}  // namespace sylva
