#include "turtle/trace.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "lstring/module_types.h"
#include "sylva/predefined_ids.h"

namespace sylva::turtle {
namespace {

template <class T>
T read(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Appends one parameter; false for structures shown only as "{...}" (always a
// module's last parameter).
bool append_parameter(std::string& out, const abi::ParamType& type, const unsigned char* p) {
  switch (type.kind) {
    case abi::ParamKind::kFloat:
      append_number(out, read<float>(p));
      return true;
    case abi::ParamKind::kSigned:
      if (type.size != sizeof(int)) break;
      out += std::to_string(read<int>(p));
      return true;
    case abi::ParamKind::kVector:
      out += '(';
      for (std::uint32_t k = 0; k < type.count; ++k) {
        if (k) out += ',';
        const unsigned char* c = p + k * type.element->size;
        append_number(out, type.element->kind == abi::ParamKind::kDouble ? read<double>(c) : read<float>(c));
      }
      out += ')';
      return true;
    case abi::ParamKind::kText: {
      const char* text = read<const char*>(p);
      out += '"';
      out += text ? text : "";
      out += '"';
      return true;
    }
    default:
      break;
  }
  out += "{...}";
  return false;
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
  std::size_t count = 0;
  const abi::ModuleType& type = predefined_module_types(&count)[id];
  out += type.name;
  if (type.param_count == 0) return;
  out += '(';
  for (std::uint32_t k = 0; k < type.param_count; ++k) {
    if (k) out += ',';
    if (!append_parameter(out, *type.params[k].type, params + type.params[k].offset)) break;
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
