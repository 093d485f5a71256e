#include "lstring/param_text.h"

#include <charconv>
#include <cstdint>
#include <cstring>

#include "lstring/param_values.h"

namespace sylva {
namespace {

using abi::ParamKind;
using abi::ParamType;

// The text of the floating-point number last written, per type and thread.
// Successive modules of a plant's string very often carry the same value
// (the segments of one generation, the same angle), and the shortest-text
// search costs far more than comparing the bits.
template <class T>
struct LastNumberText {
  T value{};
  NumberStyle style = NumberStyle::kExact;
  unsigned char length = 0;  // 0: nothing cached yet
  char text[62];
};

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
void append_float(T value, NumberStyle style, std::string& out) {
  // Small whole numbers: the shortest exact text and %g are both the
  // integer's digits. Below 10^5 the fixed form is never longer than the
  // exponent form, so to_chars would choose it too; -0 keeps its sign
  // through to_chars.
  if (value > -100000 && value < 100000 && value != 0) {
    const auto whole = static_cast<std::int32_t>(value);
    if (static_cast<T>(whole) == value) {
      char text[16];
      out.append(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, whole).ptr - text));
      return;
    }
  }
  thread_local LastNumberText<T> last;
  if (last.length && last.style == style && same_bits(last.value, value)) {
    out.append(last.text, last.length);
    return;
  }
  const std::to_chars_result r =
      style == NumberStyle::kCpfg
          ? std::to_chars(last.text, last.text + sizeof last.text, value, std::chars_format::general, 6)
          : std::to_chars(last.text, last.text + sizeof last.text, value);
  last.value = value;
  last.style = style;
  last.length = static_cast<unsigned char>(r.ptr - last.text);
  out.append(last.text, last.length);
}

template <class T>
void append_number(T value, NumberStyle style, std::string& out) {
  if constexpr (std::is_floating_point_v<T>) {
    append_float(value, style, out);
  } else {
    char text[32];
    out.append(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, value).ptr - text));
  }
}

void append_bytes(const unsigned char* at, std::size_t n, std::string& out) {
  static constexpr char kDigits[] = "0123456789abcdef";
  out += '#';
  for (std::size_t i = 0; i < n; ++i) {
    out += kDigits[at[i] >> 4];
    out += kDigits[at[i] & 15];
  }
}

void append_text(const char* text, std::string& out) {
  out += '"';
  for (const char* c = text ? text : ""; *c; ++c) {
    if (*c == '"' || *c == '\\') out += '\\';
    out += *c;
  }
  out += '"';
}

bool from_table(const ParamType* type, NumberStyle style) {
  if (!type) return false;
  switch (type->kind) {
    case ParamKind::kEnum:
    case ParamKind::kVector:
    case ParamKind::kArray: return from_table(type->element, style);
    case ParamKind::kStruct:
      // A struct without a field list has an unknown layout only if it is
      // not the model's own; with one, every field must be located.
      if (type->field_count == 0) return false;
      for (std::uint32_t k = 0; k < type->field_count; ++k)
        if (!from_table(type->fields[k].type, style)) return false;
      return true;
    case ParamKind::kText: return style == NumberStyle::kExact;
    default: return true;
  }
}

void append_value(const ParamType& type, const unsigned char* at, NumberStyle style, std::string& out) {
  switch (type.kind) {
    case ParamKind::kFloat: return append_number(load_param<float>(at), style, out);
    case ParamKind::kDouble: return append_number(load_param<double>(at), style, out);
    case ParamKind::kLongDouble: return append_number(load_param<long double>(at), style, out);
    case ParamKind::kBool: out += load_param<bool>(at) ? '1' : '0'; return;
    case ParamKind::kSigned:
    case ParamKind::kUnsigned:
      return with_integer(type, at, [&](auto v) { append_number(v, NumberStyle::kExact, out); });
    case ParamKind::kEnum: return append_value(*type.element, at, style, out);
    case ParamKind::kVector:
    case ParamKind::kArray:
      out += type.kind == ParamKind::kVector ? '(' : '[';
      for (std::uint32_t k = 0; k < type.count; ++k) {
        if (k) out += ',';
        append_value(*type.element, at + k * type.element->size, style, out);
      }
      out += type.kind == ParamKind::kVector ? ')' : ']';
      return;
    case ParamKind::kStruct:
      for (std::uint32_t k = 0; k < type.field_count; ++k) {
        const abi::ParamField& field = type.fields[k];
        out += k ? ',' : '{';
        out += field.name;
        out += '=';
        append_value(*field.type, at + field.offset, style, out);
      }
      out += '}';
      return;
    case ParamKind::kText: return append_text(load_param<const char*>(at), out);
    case ParamKind::kOther: return append_bytes(at, type.size, out);
  }
}

}  // namespace

bool params_text_from_table(std::span<const abi::ParamField> params, NumberStyle style) {
  for (const abi::ParamField& param : params)
    if (!from_table(param.type, style)) return false;
  return true;
}

void append_params_text(std::span<const abi::ParamField> params, const unsigned char* block, NumberStyle style,
                        std::string& out) {
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (k) out += ',';
    append_value(*params[k].type, block + params[k].offset, style, out);
  }
}

}  // namespace sylva
