#include "studio/parameters.h"

namespace sylva::studio {

std::vector<Parameter> find_parameters(const std::string&, const std::string&, const std::vector<io::InputFile>&,
                                       std::vector<std::string>&) {
  return {};
}

std::string apply_parameter(const std::string& text, const Parameter&) { return text; }

}  // namespace sylva::studio
