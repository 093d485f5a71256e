#include "io/string_text.h"

namespace sylva::io {

std::string format_string(const ModuleString& string, const ModuleTypes& types) {
  std::string text;
  text.reserve(string.size_bytes() * 2);
  const StringView v = string.view(types);
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    if (at != v.begin && !types.cpfg()) text += ' ';  // cpfg: no separators
    append_module_text(v, at, types, text);
  }
  text += '\n';
  return text;
}

void append_module_text(const StringView& string, std::size_t at, const ModuleTypes& types, std::string& text) {
  const ModuleId id = string.id_at(at);
  text += types.name(id);
  if (types[id].param_size > 0) {
    text += '(';
    types.format_params(id, module_params(string.data, at), text);
    text += ')';
  }
}

}  // namespace sylva::io
