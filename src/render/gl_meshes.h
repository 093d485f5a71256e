// The triangles a render draws. Unlike a mesh file, a render knows its
// camera, and uses it: circles facing the viewer are turned toward it, and
// cylinders, discs and spheres get only as many sides as their size on
// screen needs.
#pragma once

#include <vector>

#include "geometry/camera.h"
#include "geometry/scene.h"
#include "geometry/tessellation.h"

namespace sylva::io::gl {

// What the camera frames: Scene::bounds(), except that pixel-style segments
// count as their end points, their widths being pixels rather than scene units.
geometry::Box drawn_bounds(const geometry::Scene& scene, geometry::LineStyle line_style);

// The Scene as one or more meshes (primitives tessellated with the same
// number of sides share one), together everything tessellate() would make,
// except that:
//  - pixel-style segments are left out: the renderer draws them as lines;
//  - a cylinder, disc or sphere whose outline on screen would stray less
//    than half a pixel from the true circle with fewer sides than
//    `options.contour_sides` gets fewer (at least 3 for cylinders, 4 for the
//    others), and grows a little so as to cover as much of the image as it
//    would with every side. `pixel_scale` is the pixels drawn per pixel of
//    the camera's image (supersampling). With `every_side` (a wireframe
//    shows the sides), none does.
std::vector<geometry::TriangleMesh> tessellate_for_view(const geometry::Scene& scene, const geometry::Camera& camera,
                                                        const geometry::TessellationOptions& options, float pixel_scale,
                                                        bool every_side);

}  // namespace sylva::io::gl
