#include "inputs/label_font.h"

#include <charconv>
#include <vector>

namespace sylva::io {

namespace {

std::vector<std::string> x_font_fields(const std::string& name) {
  std::vector<std::string> fields;
  std::string field;
  for (char c : name) {
    if (c != '-') {
      field += c;
    } else {
      fields.push_back(field.empty() ? "*" : field);
      field.clear();
    }
  }
  if (!field.empty()) fields.push_back(field);
  return fields;
}

// The whole number a field starts with; 0 for none, or one past an int.
int leading_integer(const std::string& text) {
  int value = 0;
  if (std::from_chars(text.data(), text.data() + text.size(), value).ec != std::errc()) return 0;
  return value;
}

}  // namespace

geometry::LabelFont parse_x_font(const std::string& name, geometry::LabelFont fallback) {
  const std::vector<std::string> f = x_font_fields(name);
  if (f.size() < 8) return fallback;
  geometry::LabelFont font;
  int size = leading_integer(f[7]);
  if (size <= 0 || size > 100) size = leading_integer(f[6]);
  font.points = size > 0 ? static_cast<float>(size) : fallback.points;
  font.bold = f[3] == "bold" || f[3] == "black";
  font.italic = f[4] == "italic";
  std::string family;
  for (char c : f[2]) family += c == '_' ? ' ' : c;
  font.family = family == "*" ? fallback.family : family;
  return font;
}

geometry::LabelFont label_font(const ViewFile& view, bool cpfg) {
  const ViewFile defaults;
  const bool winfont_given = view.winfont.name != defaults.winfont.name || view.winfont.size != defaults.winfont.size ||
                             view.winfont.bold != defaults.winfont.bold || view.winfont.italic != defaults.winfont.italic;
  if (winfont_given) return geometry::LabelFont{view.winfont.name, static_cast<float>(view.winfont.size), view.winfont.bold,
                                      view.winfont.italic};
  // lpfg's default font is Times 12 whatever the X font default says.
  if (!cpfg && view.font == defaults.font) return geometry::LabelFont{};
  return parse_x_font(view.font);
}

}  // namespace sylva::io
