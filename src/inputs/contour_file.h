// Contour files (VLAB Tools manual 7.4, 7.5): B-spline contours from cuspy,
// one per .con file or several in a gallery's .cset file.
#pragma once

#include <string>
#include <vector>

#include "geometry/contour.h"

namespace sylva::io {

// Every version of the format: "cver 1 1" to "cver 1 3", and the first one
// ("n dim type" then the points). A contour without a name is named after
// the file.
geometry::Contour read_contour_file(const std::string& path);
// The same from the file's text already read; `path` names it.
geometry::Contour parse_contour(const std::string& text, const std::string& path);

// "contourgalleryver 1 1", "items: n", then n contours in the cuspy format.
std::vector<geometry::Contour> read_contour_set_file(const std::string& path);

}  // namespace sylva::io
