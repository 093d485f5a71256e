#include "io/string_text.h"

namespace sylva::io {

std::string format_string(const ModuleString& string, const ModuleTypes& types) {
  std::string text;
  text.reserve(string.size_bytes() * 2);
  const StringView v = string.view(types);
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    const ModuleId id = v.id_at(at);
    if (at != v.begin && !types.cpfg()) text += ' ';  // cpfg: no separators
    text += types.name(id);
    if (types[id].param_size > 0) {
      text += '(';
      types.format_params(id, module_params(v.data, at), text);
      text += ')';
    }
  }
  text += '\n';
  return text;
}

}  // namespace sylva::io
