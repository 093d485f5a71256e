// Writing an output file whole or not at all: the content goes to a temporary
// file beside the target, which is renamed over it only once complete.
#pragma once

#include <string>

namespace sylva::io {

// "-" writes to standard output. Throws ModelError naming the path on failure.
void write_output_file(const std::string& path, const std::string& content);

}  // namespace sylva::io
