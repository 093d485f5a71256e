// Function files (VLAB Tools manual 8.4, 8.5, 9.2, 10.3): funcedit's
// B-spline functions on [0,1], one per .func file, several in a gallery's
// .fset file, or on timelines in a .tset file.
#pragma once

#include <string>
#include <vector>

#include "geometry/function.h"

namespace sylva::io {

// "fver 1 1" files and the older "range:" ones. A function without a name is
// named after the file. A point line may give a multiplicity after x and y
// ("x y m": the point m times), as funcedit writes them.
geometry::Function read_function_file(const std::string& path);

// "funcgalleryver 1 1", "items: n", then n functions in the funcedit format.
std::vector<geometry::Function> read_function_set_file(const std::string& path);

// The timeline editor's .tset file: "timeEdit 1 2", "items: n", then n
// timelines, each "start:", "end:", "name:", optional "color:",
// "startLabel:", "endLabel:", and its function between
// "timelineFunceditFileStart:" and "timelineFunceditFileEnd:". A function
// keeps its timeline's start and end as the interval tfunc maps onto [0,1],
// and its own name (the timeline's if it has none), as lpfg names it.
std::vector<geometry::Function> read_timeline_set_file(const std::string& path);

// A function file named by cpfg's view file ("function: file samples"):
// cpfg tabulates an "fver" file at its own "samples:" and a "range:" file at
// the view file's count (none given: -1, every value bisected).
geometry::Function read_cpfg_function_file(const std::string& path, int view_samples = -1);
// A function set named by cpfg's view file ("function set: file"): as
// read_function_set_file, with cpfg's 100 samples for "range:" items.
std::vector<geometry::Function> read_cpfg_function_set_file(const std::string& path);

}  // namespace sylva::io
