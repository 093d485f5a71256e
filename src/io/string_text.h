// The text form of a string: modules separated by spaces, each as its name or
// Name(p1,p2,...), numbers printed so they read back exactly (float %.9g,
// double %.17g, structs as {field=value,...}). cpfg models are written as cpfg
// writes them: modules concatenated, parameters as %g of a float.
#pragma once

#include <string>

#include "lstring/module_string.h"
#include "lstring/module_types.h"

namespace sylva::io {

// The whole string on one line, ending with a newline.
std::string format_string(const ModuleString& string, const ModuleTypes& types);

// The module at byte offset `at` of `string`, appended to `text` as the
// string writes it: its name or Name(p1,p2,...).
void append_module_text(const StringView& string, std::size_t at, const ModuleTypes& types, std::string& text);

}  // namespace sylva::io
