// Reading parameters back from the text format_value writes (a saved
// string, LPFG manual 6.6): the inverse of format_params, value by value.
// Included by modules.h.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <type_traits>

namespace sylva::rt {

inline void skip_space(abi::TextSource* in) {
  while (in->at < in->end && (*in->at == ' ' || *in->at == '\t' || *in->at == '\n' || *in->at == '\r')) ++in->at;
}
inline bool parse_fail(abi::TextSource* in, const char* expected) {
  in->expected = expected;
  return false;
}
inline bool parse_char_if(abi::TextSource* in, char c) {
  skip_space(in);
  if (in->at < in->end && *in->at == c) {
    ++in->at;
    return true;
  }
  return false;
}
inline bool parse_char(abi::TextSource* in, char c, const char* expected) {
  return parse_char_if(in, c) || parse_fail(in, expected);
}

// A number as the C library reads it; it must end within the text.
template <class N, class Convert>
inline bool parse_number(abi::TextSource* in, N& out, Convert convert, const char* expected) {
  skip_space(in);
  char* stop = nullptr;
  const N value = convert(in->at, &stop);
  if (stop == in->at || stop > in->end) return parse_fail(in, expected);
  in->at = stop;
  out = value;
  return true;
}

template <class T>
inline bool parse_integer(abi::TextSource* in, T& out) {
  skip_space(in);
  const char* start = in->at;
  if constexpr (std::is_signed_v<T>) {
    long long v = 0;
    if (!parse_number(in, v, [](const char* s, char** e) { return std::strtoll(s, e, 10); }, "an integer"))
      return false;
    if (v < static_cast<long long>(std::numeric_limits<T>::min()) ||
        v > static_cast<long long>(std::numeric_limits<T>::max()))
      return in->at = start, parse_fail(in, "an integer in the range of the parameter's type");
    out = static_cast<T>(v);
  } else {
    if (in->at < in->end && *in->at == '-') return parse_fail(in, "an integer of 0 or more");
    unsigned long long v = 0;
    if (!parse_number(in, v, [](const char* s, char** e) { return std::strtoull(s, e, 10); }, "an integer"))
      return false;
    if (v > static_cast<unsigned long long>(std::numeric_limits<T>::max()))
      return in->at = start, parse_fail(in, "an integer in the range of the parameter's type");
    out = static_cast<T>(v);
  }
  return true;
}

template <class T>
  requires(!std::is_const_v<T>)
bool parse_value(T& v, abi::TextSource* in);

template <class S>
inline bool parse_sequence(S* xs, std::size_t n, char open, char close, abi::TextSource* in, const char* expected) {
  if (!parse_char(in, open, expected)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (i && !parse_char(in, ',', "','")) return false;
    if (!parse_value(xs[i], in)) return false;
  }
  return parse_char(in, close, close == ')' ? "')'" : "']'");
}

template <class T>
bool parse_struct(T& v, abi::TextSource* in);

inline int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

template <class T>
  requires(!std::is_const_v<T>)
bool parse_value(T& v, abi::TextSource* in) {
  if constexpr (std::is_same_v<T, float>) {
    return parse_number(in, v, [](const char* s, char** e) { return std::strtof(s, e); }, "a number");
  } else if constexpr (std::is_same_v<T, double>) {
    return parse_number(in, v, [](const char* s, char** e) { return std::strtod(s, e); }, "a number");
  } else if constexpr (std::is_same_v<T, long double>) {
    return parse_number(in, v, [](const char* s, char** e) { return std::strtold(s, e); }, "a number");
  } else if constexpr (std::is_same_v<T, bool>) {
    skip_space(in);
    if (in->at < in->end && (*in->at == '0' || *in->at == '1')) {
      v = *in->at++ == '1';
      return true;
    }
    return parse_fail(in, "0 or 1");
  } else if constexpr (std::is_enum_v<T>) {
    std::underlying_type_t<T> n{};
    if (!parse_integer(in, n)) return false;
    v = static_cast<T>(n);
    return true;
  } else if constexpr (std::is_integral_v<T>) {
    return parse_integer(in, v);
  } else if constexpr (vector_size<T> > 0) {
    return parse_sequence(&v.x, vector_size<T>, '(', ')', in, "'(' to begin a vector");
  } else if constexpr (std::is_pointer_v<T>) {
    return parse_fail(in, "a value that can be read back (a pointer cannot)");
  } else if constexpr (std::is_array_v<T>) {
    return parse_sequence(v, std::extent_v<T>, '[', ']', in, "'[' to begin an array");
  } else if constexpr (requires { sylva_parse_value(v, in); }) {
    // Structs of the model: the translator writes these overloads.
    return parse_struct(v, in);
  } else {
    // The bytes format_value writes for a type it cannot print otherwise.
    if (!parse_char(in, '#', "'#' and the bytes of the value")) return false;
    unsigned char bytes[sizeof(T)];
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      if (in->end - in->at < 2) return parse_fail(in, "two hexadecimal digits per byte of the value");
      const int hi = hex_digit(in->at[0]), lo = hex_digit(in->at[1]);
      if (hi < 0 || lo < 0) return parse_fail(in, "two hexadecimal digits per byte of the value");
      bytes[i] = static_cast<unsigned char>(hi * 16 + lo);
      in->at += 2;
    }
    std::memcpy(static_cast<void*>(&v), bytes, sizeof bytes);
    return true;
  }
}

// `name=` of a struct field; false at anything else.
inline bool parse_field_name(abi::TextSource* in, const char*& name, std::size_t& length) {
  skip_space(in);
  name = in->at;
  while (in->at < in->end && (std::isalnum(static_cast<unsigned char>(*in->at)) || *in->at == '_')) ++in->at;
  length = static_cast<std::size_t>(in->at - name);
  if (length == 0) return parse_fail(in, "a field name");
  return parse_char(in, '=', "'=' after the field name");
}
// Every field of a saved struct must be given, once: a field left out
// would otherwise read as 0 without a word. The struct readers (the
// translator's sylva_parse_value, MouseStatus's below) hold no list of their
// fields, but they offer each name they read to same_name with every field in
// declaration order until one matches; a FieldCheck in force while one of
// them runs sees those offers. Structs nest, so checks stack, per thread.
class FieldCheck {
 public:
  enum Mode { kListing, kReading };
  explicit FieldCheck(Mode mode, std::vector<const char*> fields = {})
      : mode_(mode), fields_(std::move(fields)), given_(fields_.size(), false), outer_(current()) {
    current() = this;
  }
  ~FieldCheck() { current() = outer_; }
  FieldCheck(const FieldCheck&) = delete;
  FieldCheck& operator=(const FieldCheck&) = delete;

  static FieldCheck*& current() {
    thread_local FieldCheck* check = nullptr;
    return check;
  }

  // same_name compared a name read with `field`; false turns a match into
  // a mismatch (a field given twice).
  bool offered(const char* field, bool same) {
    if (mode_ == kListing) {
      fields_.push_back(field);
      return same;
    }
    if (!same) return false;
    for (std::size_t k = 0; k < fields_.size(); ++k) {
      if (std::strcmp(fields_[k], field) != 0) continue;
      if (given_[k]) {
        twice_ = field;
        return false;
      }
      given_[k] = true;
    }
    return true;
  }

  const std::vector<const char*>& fields() const { return fields_; }
  const char* given_twice() const { return twice_; }
  const char* first_missing() const {
    for (std::size_t k = 0; k < fields_.size(); ++k)
      if (!given_[k]) return fields_[k];
    return nullptr;
  }

 private:
  Mode mode_;
  std::vector<const char*> fields_;
  std::vector<bool> given_;
  const char* twice_ = nullptr;
  FieldCheck* outer_;
};

// TextSource::expected outlives the check that words it: the reader reports
// it after the whole module has been read.
inline const char* field_message(const std::string& text) {
  thread_local std::string message;
  message = text;
  return message.c_str();
}

inline bool same_name(const char* name, std::size_t length, const char* field) {
  const bool same = std::strlen(field) == length && std::memcmp(name, field, length) == 0;
  FieldCheck* check = FieldCheck::current();
  return check ? check->offered(field, same) : same;
}
inline bool unknown_field(abi::TextSource* in, const char* name, const char* expected) {
  in->at = name;
  const FieldCheck* check = FieldCheck::current();
  if (check && check->given_twice())
    return parse_fail(in, field_message("field '" + std::string(check->given_twice()) + "' only once"));
  return parse_fail(in, expected);
}

// The fields of struct T, in declaration order, from its reader: "0" is no
// field's name (names do not begin with a digit), so the reader offers it to
// every field and fails without setting any. Empty for a value read
// otherwise than by field names (EA20Array, SurfaceObj).
template <class T>
std::vector<const char*> struct_fields(T& v) {
  static constexpr char kNoField[] = "{0=";
  abi::TextSource probe{kNoField, kNoField + 3};
  FieldCheck listing(FieldCheck::kListing);
  sylva_parse_value(v, &probe);
  return listing.fields();
}

// A struct read by its own reader, then checked for fields it left out, which
// are reported at its closing '}'.
template <class T>
bool parse_struct(T& v, abi::TextSource* in) {
  FieldCheck check(FieldCheck::kReading, struct_fields(v));
  if (!sylva_parse_value(v, in)) return false;
  if (const char* missing = check.first_missing()) {
    --in->at;  // back to the '}'
    return parse_fail(in, field_message("field '" + std::string(missing) + "' (a saved struct gives all its fields)"));
  }
  return true;
}

template <class... T>
bool parse_params(abi::TextSource* in, unsigned char* params) {
  bool ok = true;
  bool first = true;
  unsigned char* at = params;
  auto one = [&](auto tag) {
    using P = typename decltype(tag)::type;
    if (!ok) return;
    if (!first && !parse_char(in, ',', "','")) {
      ok = false;
      return;
    }
    first = false;
    P value;
    std::memcpy(static_cast<void*>(&value), at, sizeof value);
    if (!parse_value(value, in)) {
      ok = false;
      return;
    }
    std::memcpy(at, static_cast<const void*>(&value), sizeof value);
    at += sizeof value;
  };
  (one(std::type_identity<T>{}), ...);
  (void)one;
  return ok;
}

}  // namespace sylva::rt

inline bool sylva_parse_value(EA20Array& a, sylva::abi::TextSource* in) { return sylva::rt::parse_value(a.data, in); }
inline bool sylva_parse_value(SurfaceObj& s, sylva::abi::TextSource* in) {
  return sylva::rt::parse_value(s.points, in);
}

namespace sylva::rt {
// Reads "{name=value,...}": `field` reads the value of the field named
// [name, name + n) and returns false (with in->expected set) if there is none.
template <class ReadField>
bool parse_named_fields(abi::TextSource* in, ReadField field) {
  if (!parse_char(in, '{', "'{' to begin a struct")) return false;
  if (parse_char_if(in, '}')) return true;
  do {
    const char* name = nullptr;
    std::size_t n = 0;
    if (!parse_field_name(in, name, n)) return false;
    if (!field(name, n)) return false;
  } while (parse_char_if(in, ','));
  return parse_char(in, '}', "'}' to end the struct");
}
}  // namespace sylva::rt

inline bool sylva_parse_value(MouseStatus& m, sylva::abi::TextSource* in) {
  using namespace sylva::rt;
  return parse_named_fields(in, [&](const char* name, std::size_t n) {
    return same_name(name, n, "viewNum")       ? parse_value(m.viewNum, in)
           : same_name(name, n, "viewX")       ? parse_value(m.viewX, in)
           : same_name(name, n, "viewY")       ? parse_value(m.viewY, in)
           : same_name(name, n, "atFront")     ? parse_value(m.atFront, in)
           : same_name(name, n, "atRear")      ? parse_value(m.atRear, in)
           : same_name(name, n, "atMiddle")    ? parse_value(m.atMiddle, in)
           : same_name(name, n, "selectDepth") ? parse_value(m.selectDepth, in)
           : same_name(name, n, "selectPoint") ? parse_value(m.selectPoint, in)
           : same_name(name, n, "keypressed")  ? parse_value(m.keypressed, in)
           : same_name(name, n, "lbPushed")    ? parse_value(m.lbPushed, in)
           : same_name(name, n, "lbDown")      ? parse_value(m.lbDown, in)
           : same_name(name, n, "lbReleased")  ? parse_value(m.lbReleased, in)
                                               : unknown_field(in, name, "a field of MouseStatus");
  });
}
inline bool sylva_parse_value(CameraPosition& c, sylva::abi::TextSource* in) {
  using namespace sylva::rt;
  return parse_named_fields(in, [&](const char* name, std::size_t n) {
    return same_name(name, n, "position") ? parse_value(c.position, in)
           : same_name(name, n, "lookat") ? parse_value(c.lookat, in)
           : same_name(name, n, "head")   ? parse_value(c.head, in)
           : same_name(name, n, "left")   ? parse_value(c.left, in)
           : same_name(name, n, "up")     ? parse_value(c.up, in)
           : same_name(name, n, "scale")  ? parse_value(c.scale, in)
                                          : unknown_field(in, name, "a field of CameraPosition");
  });
}
