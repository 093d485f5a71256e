// Labels drawn into a rendered image (Label in lpfg, @L in cpfg): each text
// with its left end on the baseline at the label's projected position, as
// both programs draw it with Qt's renderText, in the colour index's colour
// (a material's emission colour, as their text_color takes it), over the
// scene whatever lies in front, and not at all when the position is outside
// the camera's view volume.
#pragma once

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/render_settings.h"
#include "geometry/scene.h"
#include "render/png_renderer.h"

namespace sylva::io {

void draw_labels(Image& image, const std::vector<geometry::Label>& labels, const geometry::Palette& palette,
                 const geometry::Camera& camera, const geometry::LabelFont& font);

}  // namespace sylva::io
