// Writing an output file whole or not at all: the content goes to a temporary
// file beside the target, which is renamed over it only once complete. A file
// replaced keeps its permission bits; a path that is a symbolic link is
// written through (the link stays, its target is replaced).
#pragma once

#include <string>

#include "support/whole_file.h"

namespace sylva::io {

// "-" writes to standard output. Throws ModelError naming the path (or
// standard output) on failure.
void write_output_file(const std::string& path, const std::string& content);
// The same with the content produced piece by piece (see whole_file.h).
void write_output_file(const std::string& path, const ContentProducer& produce);

// A program that prints to standard output ends with status 1 and says so
// when what it printed could not all be written (a full disk, /dev/full, a
// closed pipe), unless write_output_file already reported it.
void check_standard_output_at_exit();

}  // namespace sylva::io
