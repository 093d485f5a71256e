// Reading module parameters back from saved-string text by their type table:
// the inverse of param_text.cpp's writer, value by value. Numbers, names and
// punctuation are read by the runtime's own scanners, those the readers
// compiled into models use (sylva/runtime/parse_params.h), so a saved string
// reads back the same, and fails the same, whichever reads it.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "lstring/param_text.h"
#include "sylva/runtime/parse_params.h"

namespace sylva {
namespace {

using abi::ParamKind;
using abi::ParamType;

class TableReader {
 public:
  explicit TableReader(abi::TextSource* in) : in_(in) {}

  bool value(const ParamType& type, unsigned char* at) {
    switch (type.kind) {
      case ParamKind::kFloat: return scalar<float>(at);
      case ParamKind::kDouble: return scalar<double>(at);
      case ParamKind::kLongDouble: return scalar<long double>(at);
      case ParamKind::kBool: return scalar<bool>(at);
      case ParamKind::kSigned:
      case ParamKind::kUnsigned: return integer(type, at);
      case ParamKind::kEnum: return value(*type.element, at);
      case ParamKind::kVector: return sequence(type, at, '(', ')', "'(' to begin a vector");
      case ParamKind::kArray: return sequence(type, at, '[', ']', "'[' to begin an array");
      case ParamKind::kStruct: return structure(type, at);
      case ParamKind::kText: return rt::parse_fail(in_, "a value that can be read back (a pointer cannot)");
      case ParamKind::kOther: return bytes(type, at);
    }
    return rt::parse_fail(in_, "a parameter value");
  }

 private:
  template <class T>
  bool scalar(unsigned char* at) {
    T v{};
    if (!rt::parse_value(v, in_)) return false;
    std::memcpy(at, &v, sizeof v);
    return true;
  }

  bool integer(const ParamType& type, unsigned char* at) {
    const bool is_signed = type.kind == ParamKind::kSigned;
    switch (type.size) {
      case 1: return is_signed ? scalar<std::int8_t>(at) : scalar<std::uint8_t>(at);
      case 2: return is_signed ? scalar<std::int16_t>(at) : scalar<std::uint16_t>(at);
      case 4: return is_signed ? scalar<std::int32_t>(at) : scalar<std::uint32_t>(at);
      default: return is_signed ? scalar<std::int64_t>(at) : scalar<std::uint64_t>(at);
    }
  }

  bool sequence(const ParamType& type, unsigned char* at, char open, char close, const char* expected) {
    if (!rt::parse_char(in_, open, expected)) return false;
    for (std::uint32_t k = 0; k < type.count; ++k) {
      if (k && !rt::parse_char(in_, ',', "','")) return false;
      if (!value(*type.element, at + k * type.element->size)) return false;
    }
    return rt::parse_char(in_, close, close == ')' ? "')'" : "']'");
  }

  // {name=value,...}: every field once, in any order; a field left out is
  // reported at the closing '}', as it would otherwise read as 0 unsaid.
  bool structure(const ParamType& type, unsigned char* at) {
    if (!rt::parse_char(in_, '{', "'{' to begin a struct")) return false;
    std::vector<bool> given(type.field_count, false);
    if (!rt::parse_char_if(in_, '}')) {
      do {
        const char* name = nullptr;
        std::size_t length = 0;
        if (!rt::parse_field_name(in_, name, length)) return false;
        std::uint32_t k = 0;
        while (k < type.field_count &&
               !(std::strlen(type.fields[k].name) == length && std::memcmp(type.fields[k].name, name, length) == 0))
          ++k;
        if (k == type.field_count || given[k]) {
          in_->at = name;
          if (k < type.field_count)
            return rt::parse_fail(in_, rt::field_message("field '" + std::string(name, length) + "' only once"));
          return rt::parse_fail(in_, rt::field_message(std::string("a field of ") + (type.name ? type.name : "the struct")));
        }
        given[k] = true;
        if (!value(*type.fields[k].type, at + type.fields[k].offset)) return false;
      } while (rt::parse_char_if(in_, ','));
      if (!rt::parse_char(in_, '}', "'}' to end the struct")) return false;
    }
    for (std::uint32_t k = 0; k < type.field_count; ++k) {
      if (given[k]) continue;
      --in_->at;  // back to the '}'
      return rt::parse_fail(
          in_, rt::field_message("field '" + std::string(type.fields[k].name) + "' (a saved struct gives all its fields)"));
    }
    return true;
  }

  // '#' and two hexadecimal digits per byte: a value of unknown layout.
  bool bytes(const ParamType& type, unsigned char* at) {
    if (!rt::parse_char(in_, '#', "'#' and the bytes of the value")) return false;
    for (std::uint32_t i = 0; i < type.size; ++i) {
      const int hi = in_->end - in_->at < 2 ? -1 : rt::hex_digit(in_->at[0]);
      const int lo = hi < 0 ? -1 : rt::hex_digit(in_->at[1]);
      if (lo < 0) return rt::parse_fail(in_, "two hexadecimal digits per byte of the value");
      at[i] = static_cast<unsigned char>(hi * 16 + lo);
      in_->at += 2;
    }
    return true;
  }

  abi::TextSource* in_;
};

}  // namespace

bool read_params_text(std::span<const abi::ParamField> params, abi::TextSource* in, unsigned char* block) {
  TableReader reader(in);
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (k && !rt::parse_char(in, ',', "','")) return false;
    if (!reader.value(*params[k].type, block + params[k].offset)) return false;
  }
  return true;
}

}  // namespace sylva
