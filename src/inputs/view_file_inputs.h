// Reading the files a view file names into the run's inputs: its surfaces,
// and cpfg's contours, functions and curves (read_input_files calls it).
#pragma once

#include "inputs/input_files.h"

namespace sylva::io {

// Adds `inputs.view`'s files to `inputs`, relative to the view file. A file
// that cannot be read is a warning, with what lpfg or cpfg does without it.
void read_view_file_inputs(InputFiles& inputs);

}  // namespace sylva::io
