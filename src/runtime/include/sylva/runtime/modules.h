// How compiled models read, write and print modules.
//
// The translator turns `produce A(x) B;` into calls of `put_module<...>` and the
// formal parameters of a predecessor into `param<I, ...>` reads; the module
// table it generates uses `module_type<...>`: the parameters' types
// (param_types.h), their printer and their reader. Parameters are packed in
// declaration order without padding (see sylva/abi.h).
#pragma once

#include <sylva/abi.h>
#include <sylva/predefined_ids.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <charconv>
#include <cstring>
#include <type_traits>

namespace sylva::rt {

template <class... T>
inline constexpr std::size_t params_size = (std::size_t{0} + ... + sizeof(T));

template <std::size_t I, class... T>
struct ParamAt;
template <class First, class... Rest>
struct ParamAt<0, First, Rest...> {
  using type = First;
  static constexpr std::size_t offset = 0;
};
template <std::size_t I, class First, class... Rest>
struct ParamAt<I, First, Rest...> {
  using type = typename ParamAt<I - 1, Rest...>::type;
  static constexpr std::size_t offset = sizeof(First) + ParamAt<I - 1, Rest...>::offset;
};

// The I-th parameter of a module whose parameter types are T...
template <std::size_t I, class... T>
inline typename ParamAt<I, T...>::type param(const unsigned char* params) {
  typename ParamAt<I, T...>::type value;
  std::memcpy(static_cast<void*>(&value), params + ParamAt<I, T...>::offset, sizeof value);
  return value;
}

template <class T>
inline void put_param(unsigned char*& at, const T& value) {
  if constexpr (std::is_class_v<T> && sizeof(T) > 8 && sizeof(T) % 4 == 0 && alignof(T) >= 4) {
    // A struct a rule body has just set field by field: copied a word at a
    // time, each read is answered by the store of its own field. Read whole
    // (16 bytes at once), it waits until those stores reach the cache, which
    // cost the structs benchmark a fifth of its rule bodies' time.
    // (The empty asm keeps the compiler from merging the words again.)
    const auto* from = reinterpret_cast<const unsigned char*>(&value);
    for (std::size_t k = 0; k < sizeof(T); k += 4) {
      std::uint32_t word;
      std::memcpy(&word, from + k, 4);
      __asm__("" : "+r"(word));
      std::memcpy(at + k, &word, 4);
    }
  } else {
    std::memcpy(at, static_cast<const void*>(&value), sizeof value);
  }
  at += sizeof value;
}

// Room for one module with parameters T... in a string, whatever its id.
template <class... T>
inline constexpr std::size_t module_bytes = abi::largest_module_size(params_size<T...>);

// How put_module takes a parameter: a struct by reference, so that its words
// are read where the body set them (put_param); the rest by value, so that a
// wrong argument is reported as one that cannot convert.
template <class T>
using produced_argument = std::conditional_t<std::is_class_v<T>, const T&, T>;

// Writes one module at `at` (room for it has been reserved) and advances
// `at`. Arguments convert to the declared parameter types as they would in a
// function call. A produce statement reserves room for all its modules once,
// then writes them one after another.
template <class... T>
inline void put_module(unsigned char*& at, abi::ModuleId id, produced_argument<T>... values) {
  if constexpr (params_size<T...> != 0) {
    abi::put_leading_id(at, id);
    (put_param<T>(at, values), ...);
    abi::put_trailing_id(at, id);
  } else {
    abi::put_parameterless(at, id);
  }
}

// Writes `n` bytes of modules the translator encoded itself (those whose
// arguments are all literals) and advances `at`.
inline void put_encoded_modules(unsigned char*& at, const char* bytes, std::size_t n) {
  std::memcpy(at, bytes, n);
  at += n;
}

// ---- Printing parameters so that they read back exactly -------------------
// The engine prints most parameters from their table (see module_type below);
// these printers serve the types it cannot (a struct with a bit-field), in
// the same text: the shortest form that reads back to the same value.

template <class N>
inline void format_number(abi::TextSink* out, N v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  out->write(buf, static_cast<std::size_t>(r.ptr - buf));
}

template <class T>
void format_value(const T& v, abi::TextSink* out);

template <class S>
inline void format_vector(const S* xs, int n, abi::TextSink* out) {
  out->write("(", 1);
  for (int i = 0; i < n; ++i) {
    if (i) out->write(",", 1);
    format_value(xs[i], out);
  }
  out->write(")", 1);
}

template <class T>
void format_value(const T& v, abi::TextSink* out) {
  if constexpr (std::is_floating_point_v<T>) {
    format_number(out, v);
  } else if constexpr (std::is_same_v<T, bool>) {
    out->write(v ? "1" : "0", 1);
  } else if constexpr (std::is_enum_v<T>) {
    format_number(out, static_cast<std::underlying_type_t<T>>(v));
  } else if constexpr (std::is_integral_v<T>) {
    if constexpr (std::is_signed_v<T>) format_number(out, static_cast<long long>(v));
    else format_number(out, static_cast<unsigned long long>(v));
  } else if constexpr (vector_size<T> > 0) {
    format_vector(&v.x, vector_size<T>, out);
  } else if constexpr (std::is_same_v<T, const char*> || std::is_same_v<T, char*>) {
    out->write("\"", 1);
    for (const char* c = v ? v : ""; *c; ++c) {
      if (*c == '"' || *c == '\\') out->write("\\", 1);
      out->write(c, 1);
    }
    out->write("\"", 1);
  } else if constexpr (std::is_array_v<T>) {
    out->write("[", 1);
    for (std::size_t i = 0; i < std::extent_v<T>; ++i) {
      if (i) out->write(",", 1);
      format_value(v[i], out);
    }
    out->write("]", 1);
  } else if constexpr (requires { sylva_format_value(v, out); }) {
    // Structs of the model: the translator writes these overloads.
    sylva_format_value(v, out);
  } else {
    // A type nothing knows how to print: its bytes, so it still reads back.
    static const char digits[] = "0123456789abcdef";
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&v);
    out->write("#", 1);
    for (std::size_t i = 0; i < sizeof v; ++i) {
      char pair[2] = {digits[bytes[i] >> 4], digits[bytes[i] & 15]};
      out->write(pair, 2);
    }
  }
}

template <class... T>
void format_params(const unsigned char* params, abi::TextSink* out) {
  bool first = true;
  auto one = [&](auto tag, const unsigned char*& at) {
    using P = typename decltype(tag)::type;
    P value;
    std::memcpy(static_cast<void*>(&value), at, sizeof value);
    at += sizeof value;
    if (!first) out->write(",", 1);
    first = false;
    format_value(value, out);
  };
  const unsigned char* at = params;
  (one(std::type_identity<T>{}, at), ...);
  (void)at;
  (void)one;  // a module without parameters never calls it
}

}  // namespace sylva::rt

#include <sylva/runtime/param_types.h>
#include <sylva/runtime/parse_params.h>

namespace sylva::rt {

// Parameters the engine can write from their table get no printer and no
// reader of their own (the engine reads them from the table too): two fewer
// templates for the model to compile, the reader of a struct by far the
// larger.
template <class... T>
abi::ModuleType module_type(const char* name) {
  decltype(abi::ModuleType::format_params) printer = nullptr;
  decltype(abi::ModuleType::parse_params) reader = nullptr;
  if constexpr (!(text_from_table<T>() && ...)) {
    printer = &format_params<T...>;
    reader = &parse_params<T...>;
  }
  return abi::ModuleType{name, static_cast<std::uint32_t>(params_size<T...>), printer,
                         static_cast<std::uint32_t>(sizeof...(T)), reader, param_fields<T...>()};
}

// A predefined module's entry: the engine supplies its printer, reader and
// parameters' types, so models do not compile them for each of the
// predefined modules.
template <class... T>
constexpr abi::ModuleType predefined_module_type(const char* name) {
  return abi::ModuleType{name, static_cast<std::uint32_t>(params_size<T...>), nullptr,
                         static_cast<std::uint32_t>(sizeof...(T)), nullptr, nullptr};
}

}  // namespace sylva::rt

inline void sylva_format_value(const EA20Array& a, sylva::abi::TextSink* out) {
  sylva::rt::format_value(a.data, out);
}
inline void sylva_format_value(const SurfaceObj& s, sylva::abi::TextSink* out) {
  sylva::rt::format_value(s.points, out);
}
inline void sylva_format_value(const MouseStatus& m, sylva::abi::TextSink* out) {
  using sylva::rt::format_value;
  out->write("{viewNum=");     format_value(m.viewNum, out);
  out->write(",viewX=");       format_value(m.viewX, out);
  out->write(",viewY=");       format_value(m.viewY, out);
  out->write(",atFront=");     format_value(m.atFront, out);
  out->write(",atRear=");      format_value(m.atRear, out);
  out->write(",atMiddle=");    format_value(m.atMiddle, out);
  out->write(",selectDepth="); format_value(m.selectDepth, out);
  out->write(",selectPoint="); format_value(m.selectPoint, out);
  out->write(",keypressed=");  format_value(m.keypressed, out);
  out->write(",lbPushed=");    format_value(m.lbPushed, out);
  out->write(",lbDown=");      format_value(m.lbDown, out);
  out->write(",lbReleased=");  format_value(m.lbReleased, out);
  out->write("}");
}
inline void sylva_format_value(const CameraPosition& c, sylva::abi::TextSink* out) {
  using sylva::rt::format_value;
  out->write("{position="); format_value(c.position, out);
  out->write(",lookat=");   format_value(c.lookat, out);
  out->write(",head=");     format_value(c.head, out);
  out->write(",left=");     format_value(c.left, out);
  out->write(",up=");       format_value(c.up, out);
  out->write(",scale=");    format_value(c.scale, out);
  out->write("}");
}
