// Colour files (VLAB Tools manual 3 and 4.4): a colormap (.map) gives 256
// colours, a material file (.mat) up to 256 Phong materials.
#pragma once

#include <string>

#include "geometry/material.h"

namespace sylva::io {

// 768 bytes: 256 R, G, B byte triplets, index 0 first.
geometry::Palette read_colormap_file(const std::string& path);

// 15-byte records: id, transparency, ambient RGB, diffuse RGB, emission RGB,
// specular RGB, shininess. Indices the file does not name keep the default
// material.
geometry::Palette read_material_file(const std::string& path);

}  // namespace sylva::io
