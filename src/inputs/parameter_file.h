// Parameter files (.vset, LPFG manual 6.2.1): one "#define name value" per
// line, read by a model with val(name).
#pragma once

#include <string>
#include <vector>

namespace sylva::io {

struct Parameter {
  std::string name;
  float value = 0;
};

// The parameters in file order. Blank lines and // comments are skipped;
// anything else is a ModelError pointing at it.
std::vector<Parameter> read_parameter_file(const std::string& path);

}  // namespace sylva::io
