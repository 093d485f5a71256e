#include "turtle/trace.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "sylva/predefined_ids.h"

namespace sylva::turtle {
namespace {

const char* const kNames[] = {
#define SYLVA_MODULE(name, ...) #name,
#include "sylva/predefined_modules.def"
};
// Each module's parameter types as the list spells them, e.g. "V3f, float".
const char* const kParameterTypes[] = {
#define SYLVA_MODULE(name, ...) "" #__VA_ARGS__,
#include "sylva/predefined_modules.def"
};

template <class T>
T read(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Appends one parameter of type `type` at `p`; returns its size, or 0 for
// structures shown only as "{...}" (always a module's last parameter).
std::size_t append_parameter(std::string& out, std::string_view type, const unsigned char* p) {
  if (type == "float") {
    append_number(out, read<float>(p));
    return 4;
  }
  if (type == "int") {
    out += std::to_string(read<int>(p));
    return 4;
  }
  if (type == "V2f" || type == "V3f" || type == "V2d" || type == "V3d") {
    const bool wide = type[2] == 'd';
    const int n = type[1] - '0';
    const std::size_t size = wide ? 8 : 4;
    out += '(';
    for (int k = 0; k < n; ++k) {
      if (k) out += ',';
      const unsigned char* c = p + static_cast<std::size_t>(k) * size;
      append_number(out, wide ? read<double>(c) : static_cast<double>(read<float>(c)));
    }
    out += ')';
    return static_cast<std::size_t>(n) * size;
  }
  if (type == "const char*") {
    const char* text = read<const char*>(p);
    out += '"';
    out += text ? text : "";
    out += '"';
    return sizeof(const char*);
  }
  out += "{...}";
  return 0;
}

}  // namespace

void append_number(std::string& out, double value) {
  // Rounding noise around zero (cos 90 in float) reads as zero.
  if (std::fabs(value) < 5e-7) value = 0;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  out += buffer;
}

void append_vector(std::string& out, geometry::Vec3 v) {
  out += '(';
  append_number(out, v.x);
  out += ',';
  append_number(out, v.y);
  out += ',';
  append_number(out, v.z);
  out += ')';
}

void append_module(std::string& out, abi::ModuleId id, const unsigned char* params) {
  if (id >= rt::mid::PredefinedCount) return;
  out += kNames[id];
  std::string_view types = kParameterTypes[id];
  if (types.empty()) return;
  out += '(';
  const unsigned char* p = params;
  bool first = true;
  while (!types.empty()) {
    std::size_t comma = types.find(',');
    std::string_view type = types.substr(0, comma);
    types = comma == std::string_view::npos ? std::string_view{} : types.substr(comma + 1);
    while (!type.empty() && type.front() == ' ') type.remove_prefix(1);
    while (!type.empty() && type.back() == ' ') type.remove_suffix(1);
    if (!first) out += ',';
    first = false;
    const std::size_t size = append_parameter(out, type, p);
    if (size == 0) break;
    p += size;
  }
  out += ')';
}

void append_cpfg_module(std::string& out, const std::string& symbol, const unsigned char* params, int count,
                        bool label) {
  out += symbol;
  if (label) {
    // @L("format", p1, ...): the text's pointer, then the floats.
    const char* text = read<const char*>(params);
    out += "(\"";
    out += text ? text : "";
    out += '"';
    for (int k = 0; k < count; ++k) {
      out += ',';
      append_number(out, read<float>(params + sizeof(const char*) + 4 * static_cast<std::size_t>(k)));
    }
    out += ')';
    return;
  }
  if (count == 0) return;
  out += '(';
  for (int k = 0; k < count; ++k) {
    if (k) out += ',';
    append_number(out, read<float>(params + 4 * static_cast<std::size_t>(k)));
  }
  out += ')';
}

}  // namespace sylva::turtle
