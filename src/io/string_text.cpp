#include "io/string_text.h"

#include <algorithm>

namespace sylva::io {

void write_string_text(const ModuleString& string, const ModuleTypes& types, const ContentSink& sink) {
  constexpr std::size_t kPiece = std::size_t{1} << 20;
  std::string text;
  text.reserve(std::min(kPiece, string.size_bytes() * 2) + 4096);
  const StringView v = string.view(types);
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    if (at != v.begin && !types.cpfg()) text += ' ';  // cpfg: no separators
    append_module_text(v, at, types, text);
    if (text.size() >= kPiece) {
      sink(text);
      text.clear();
    }
  }
  text += '\n';
  sink(text);
}

std::string format_string(const ModuleString& string, const ModuleTypes& types) {
  std::string text;
  text.reserve(string.size_bytes() * 2);
  write_string_text(string, types, [&text](std::string_view piece) { text += piece; });
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
