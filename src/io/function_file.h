// Function files (VLAB Tools manual 8.4, 8.5, 9.2): funcedit's B-spline
// functions on [0,1], one per .func file or several in a gallery's .fset file.
#pragma once

#include <string>
#include <vector>

#include "geometry/function.h"

namespace sylva::io {

// "fver 1 1" files and the older "range:" ones. A function without a name is
// named after the file.
geometry::Function read_function_file(const std::string& path);

// "funcgalleryver 1 1", "items: n", then n functions in the funcedit format.
std::vector<geometry::Function> read_function_set_file(const std::string& path);

}  // namespace sylva::io
