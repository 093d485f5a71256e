// Reading back the text form of a string that format_string writes (saved by
// OutputString or --string): module names looked up in the model's registry,
// parameters read by each module type's own reader, so they come back with
// the exact values and types they had.
#pragma once

#include <string>

#include "lstring/module_string.h"
#include "lstring/module_types.h"

namespace sylva::io {

// `text` came from `path` (named in errors). Throws ModelError at the
// line and column of the saved text for an unknown module, a wrong number of
// parameters, a struct field left out or given twice, or a malformed value.
ModuleString parse_string(const std::string& text, const ModuleTypes& types, const std::string& path);

// The same, reading the file first. A missing file, a directory or a file of
// no bytes (OutputString writes at least a newline) is an error.
ModuleString read_string_file(const std::string& path, const ModuleTypes& types);

}  // namespace sylva::io
