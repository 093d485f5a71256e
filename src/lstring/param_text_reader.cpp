// Reading module parameters back from saved-string text by their type table:
// the inverse of param_text.cpp's writer, value by value, with the messages
// of the readers compiled into models (sylva/runtime/parse_params.h), so a
// saved string reads back the same, and fails the same, whichever reads it.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "lstring/param_text.h"

namespace sylva {
namespace {

using abi::ParamKind;
using abi::ParamType;

// TextSource::expected outlives the reader: the string reader reports it
// after the whole module has been read.
const char* lasting(const std::string& text) {
  thread_local std::string message;
  message = text;
  return message.c_str();
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

class TableReader {
 public:
  explicit TableReader(abi::TextSource* in) : in_(in) {}

  bool value(const ParamType& type, unsigned char* at) {
    switch (type.kind) {
      case ParamKind::kFloat: return number<float>(at, [](const char* s, char** e) { return std::strtof(s, e); });
      case ParamKind::kDouble: return number<double>(at, [](const char* s, char** e) { return std::strtod(s, e); });
      case ParamKind::kLongDouble:
        return number<long double>(at, [](const char* s, char** e) { return std::strtold(s, e); });
      case ParamKind::kBool: {
        skip_space();
        if (in_->at < in_->end && (*in_->at == '0' || *in_->at == '1')) {
          *at = *in_->at++ == '1';
          return true;
        }
        return fail("0 or 1");
      }
      case ParamKind::kSigned:
      case ParamKind::kUnsigned: return integer(type, at);
      case ParamKind::kEnum: return value(*type.element, at);
      case ParamKind::kVector: return sequence(type, at, '(', ')', "'(' to begin a vector");
      case ParamKind::kArray: return sequence(type, at, '[', ']', "'[' to begin an array");
      case ParamKind::kStruct: return structure(type, at);
      case ParamKind::kText: return fail("a value that can be read back (a pointer cannot)");
      case ParamKind::kOther: return bytes(type, at);
    }
    return fail("a parameter value");
  }

  bool expect(char c, const char* expected) { return next_is(c) || fail(expected); }

 private:
  void skip_space() {
    while (in_->at < in_->end && (*in_->at == ' ' || *in_->at == '\t' || *in_->at == '\n' || *in_->at == '\r'))
      ++in_->at;
  }
  bool fail(const char* expected) {
    in_->expected = expected;
    return false;
  }
  bool next_is(char c) {
    skip_space();
    if (in_->at < in_->end && *in_->at == c) {
      ++in_->at;
      return true;
    }
    return false;
  }

  // A number as the C library reads it; it must end within the text.
  template <class N, class Convert>
  bool read_number(N& out, Convert convert, const char* expected) {
    skip_space();
    char* stop = nullptr;
    const N value = convert(in_->at, &stop);
    if (stop == in_->at || stop > in_->end) return fail(expected);
    in_->at = stop;
    out = value;
    return true;
  }
  template <class N, class Convert>
  bool number(unsigned char* at, Convert convert) {
    N value{};
    if (!read_number(value, convert, "a number")) return false;
    std::memcpy(at, &value, sizeof value);
    return true;
  }

  bool integer(const ParamType& type, unsigned char* at) {
    skip_space();
    const char* start = in_->at;
    const unsigned bits = 8 * type.size;
    if (type.kind == ParamKind::kSigned) {
      long long v = 0;
      if (!read_number(v, [](const char* s, char** e) { return std::strtoll(s, e, 10); }, "an integer")) return false;
      const long long max = bits >= 64 ? std::numeric_limits<long long>::max() : (1LL << (bits - 1)) - 1;
      if (v < -max - 1 || v > max) return in_->at = start, fail("an integer in the range of the parameter's type");
      store_low_bytes(static_cast<unsigned long long>(v), type.size, at);
    } else {
      if (in_->at < in_->end && *in_->at == '-') return fail("an integer of 0 or more");
      unsigned long long v = 0;
      if (!read_number(v, [](const char* s, char** e) { return std::strtoull(s, e, 10); }, "an integer"))
        return false;
      const unsigned long long max = bits >= 64 ? std::numeric_limits<unsigned long long>::max() : (1ULL << bits) - 1;
      if (v > max) return in_->at = start, fail("an integer in the range of the parameter's type");
      store_low_bytes(v, type.size, at);
    }
    return true;
  }
  // The integer's `size` bytes as an integer of that size holds them (two's
  // complement, this machine's byte order).
  static void store_low_bytes(unsigned long long v, std::uint32_t size, unsigned char* at) {
    switch (size) {
      case 1: { const auto x = static_cast<std::uint8_t>(v); std::memcpy(at, &x, 1); return; }
      case 2: { const auto x = static_cast<std::uint16_t>(v); std::memcpy(at, &x, 2); return; }
      case 4: { const auto x = static_cast<std::uint32_t>(v); std::memcpy(at, &x, 4); return; }
      default: std::memcpy(at, &v, sizeof v); return;
    }
  }

  bool sequence(const ParamType& type, unsigned char* at, char open, char close, const char* expected) {
    if (!expect(open, expected)) return false;
    for (std::uint32_t k = 0; k < type.count; ++k) {
      if (k && !expect(',', "','")) return false;
      if (!value(*type.element, at + k * type.element->size)) return false;
    }
    return expect(close, close == ')' ? "')'" : "']'");
  }

  // {name=value,...}: every field once, in any order; a field left out is
  // reported at the closing '}', as it would otherwise read as 0 unsaid.
  bool structure(const ParamType& type, unsigned char* at) {
    if (!expect('{', "'{' to begin a struct")) return false;
    std::vector<bool> given(type.field_count, false);
    if (!next_is('}')) {
      do {
        skip_space();
        const char* name = in_->at;
        while (in_->at < in_->end && is_name_char(*in_->at)) ++in_->at;
        const auto length = static_cast<std::size_t>(in_->at - name);
        if (length == 0) return fail("a field name");
        if (!expect('=', "'=' after the field name")) return false;
        std::uint32_t k = 0;
        while (k < type.field_count &&
               !(std::strlen(type.fields[k].name) == length && std::memcmp(type.fields[k].name, name, length) == 0))
          ++k;
        if (k == type.field_count || given[k]) {
          in_->at = name;
          if (k < type.field_count) return fail(lasting("field '" + std::string(name, length) + "' only once"));
          return fail(lasting(std::string("a field of ") + (type.name ? type.name : "the struct")));
        }
        given[k] = true;
        if (!value(*type.fields[k].type, at + type.fields[k].offset)) return false;
      } while (next_is(','));
      if (!expect('}', "'}' to end the struct")) return false;
    }
    for (std::uint32_t k = 0; k < type.field_count; ++k) {
      if (given[k]) continue;
      --in_->at;  // back to the '}'
      return fail(lasting("field '" + std::string(type.fields[k].name) + "' (a saved struct gives all its fields)"));
    }
    return true;
  }

  // '#' and two hexadecimal digits per byte: a value of unknown layout.
  bool bytes(const ParamType& type, unsigned char* at) {
    if (!expect('#', "'#' and the bytes of the value")) return false;
    for (std::uint32_t i = 0; i < type.size; ++i) {
      const int hi = in_->end - in_->at < 2 ? -1 : hex_digit(in_->at[0]);
      const int lo = hi < 0 ? -1 : hex_digit(in_->at[1]);
      if (lo < 0) return fail("two hexadecimal digits per byte of the value");
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
    if (k && !reader.expect(',', "','")) return false;
    if (!reader.value(*params[k].type, block + params[k].offset)) return false;
  }
  return true;
}

}  // namespace sylva
