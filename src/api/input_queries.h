// Answers a model's questions about its input files (func, curveXYZ,
// GetSurface ...; LPFG manual 6.2) from the files read at start.
#pragma once

#include "io/input_files.h"

namespace sylva {

// The ControlState::input_query callback; `inputs` is an io::InputFiles.
bool answer_input_query(void* inputs, int query, int id, const double* in, double* out);

// "-D name=id" for every function of the input files, as lpfg defines them
// (ids from 1 in command-line order), so models can write func(name, x).
std::vector<std::string> function_name_defines(const io::InputFiles& inputs);

}  // namespace sylva
