// The text form of a string: modules separated by spaces, each as its name or
// Name(p1,p2,...), numbers printed so they read back exactly (the shortest
// such text; structs as {field=value,...}; see lstring/param_text.h). cpfg
// models are written as cpfg writes them: modules concatenated, parameters
// as %g of a float.
#pragma once

#include <string>

#include "support/whole_file.h"

#include "lstring/module_string.h"
#include "lstring/module_types.h"

namespace sylva::io {

// The whole string on one line, ending with a newline, handed to `sink` in
// pieces of about a megabyte: the text is never whole in memory.
void write_string_text(const ModuleString& string, const ModuleTypes& types, const ContentSink& sink);

// The same text as one std::string.
std::string format_string(const ModuleString& string, const ModuleTypes& types);

// The module at byte offset `at` of `string`, appended to `text` as the
// string writes it: its name or Name(p1,p2,...).
void append_module_text(const StringView& string, std::size_t at, const ModuleTypes& types, std::string& text);

}  // namespace sylva::io
