// What a compiled cpfg model calls besides the L+C runtime (CPFG manual,
// chapter 5): the functions of its expressions as cpfg computes them (angles
// in degrees, cpfg's random functions, files), and its modules' entries in
// the module table, whose parameters are all floats as cpfg prints them.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/cpfg_random.h>
#include <sylva/runtime/functions.h>
#include <sylva/runtime/input_functions.h>
#include <sylva/runtime/param_types.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <utility>

namespace sylva::rt::cpfg {

// ---- Expressions (CPFG manual 5.2) ------------------------------------------

inline constexpr double kDegree = 3.14159265358979323846 / 180.0;
inline double sin(double a) { return std::sin(a * kDegree); }
inline double cos(double a) { return std::cos(a * kDegree); }
inline double tan(double a) { return std::tan(a * kDegree); }
inline double asin(double x) { return std::asin(x) / kDegree; }
inline double acos(double x) { return std::acos(x) / kDegree; }
inline double atan(double x) { return std::atan(x) / kDegree; }
inline double atan(double x, double y) { return std::atan2(y, x) / kDegree; }
inline double atan2(double y, double x) { return std::atan2(y, x) / kDegree; }
inline double pow(double x, double y) { return std::pow(x, y); }
inline double sign(double x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0; }

// ran, nran, bran, biran and srand: cpfg's own stream and methods.
inline Random random;
inline double ran(double x) { return random.ran(x); }
inline double srand(double seed) {
  if (!::sylva::rt::control.seed_fixed) random.srand(seed);
  return 0.0;
}
inline double nran(double mean, double sd) { return random.nran(mean, sd); }
inline double bran(double a, double b) { return random.bran(a, b); }
inline double biran(double n, double p) { return random.biran(n, p); }

inline double func(double id, double x) { return cpfg_func(static_cast<int>(id), x); }
inline double curve_x(double id, double t) { return ::curveX(static_cast<int>(id), static_cast<float>(t)); }
inline double curve_y(double id, double t) { return ::curveY(static_cast<int>(id), static_cast<float>(t)); }
inline double curve_z(double id, double t) { return ::curveZ(static_cast<int>(id), static_cast<float>(t)); }
inline double curve_length(double id) { return ::curveGAL(static_cast<int>(id)); }

// vvXmin() ... vvScale(): the K-th number of the view volume.
template <int K>
double view_volume(double) {
  double out[7] = {0, 0, 0, 0, 0, 0, 1};
  ask_inputs(abi::kQueryCpfgViewVolume, 0, nullptr, out, "the view volume");
  return out[K];
}

// stop(n) (CPFG manual 5.6): the run ends after this step; without a window
// to keep drawing in, n = 1 ("draw and continue") ends it the same way.
inline double stop(double = 0) {
  ::Stop();
  return 0.0;
}

// ---- Files opened by the model: fopen returns 1, 2, ...; 0 when it fails ----

inline constexpr int kMaxFiles = 64;
inline std::FILE* files[kMaxFiles];

inline std::FILE* file(double id) {
  const long k = std::lround(id);
  return k >= 1 && k <= kMaxFiles ? files[k - 1] : nullptr;
}

inline double fopen(const char* name, const char* mode) {
  for (int k = 0; k < kMaxFiles; ++k) {
    if (files[k]) continue;
    files[k] = std::fopen(name, mode[0] == 'w' ? "w" : mode[0] == 'a' ? "a" : "r");
    if (files[k]) return k + 1;
    char text[300];
    std::snprintf(text, sizeof text, "fopen: cannot open %s\n", name);
    message(text);
    return 0;
  }
  message("fopen: too many open files\n");
  return 0;
}

inline double fclose(double id) {
  std::FILE* f = file(id);
  if (!f) return -1;
  files[std::lround(id) - 1] = nullptr;
  return std::fclose(f);
}

inline double fflush(double id) {
  std::FILE* f = file(id);
  return f ? std::fflush(f) : -1;
}

template <class... Values>
double fprintf(double id, const char* format, Values... values) {
  std::FILE* f = file(id);
  return f ? std::fprintf(f, format, values...) : -1;
}

template <class... Targets>
double fscan(double id, const char* format, Targets... targets) {
  std::FILE* f = file(id);
  return f ? std::fscanf(f, format, targets...) : -1;
}

// True while the derivation probes which productions apply (kModelProbeProductions).
inline bool probing = false;

// ---- Module types -----------------------------------------------------------

inline float float_at(const unsigned char* params, std::size_t k) {
  float v;
  std::memcpy(&v, params + sizeof v * k, sizeof v);
  return v;
}

inline void write_number(abi::TextSink* out, const char* format, float v) {
  char text[48];
  const int n = std::snprintf(text, sizeof text, format, static_cast<double>(v));
  out->write(text, static_cast<std::size_t>(n));
}

// cpfg prints every parameter as %g of its float.
template <std::size_t N>
void format_floats(const unsigned char* params, abi::TextSink* out) {
  for (std::size_t k = 0; k < N; ++k) write_number(out, k ? ",%g" : "%g", float_at(params, k));
}

// @L("format", p1, ...): the string quoted with C escapes, as a cpfg model
// writes it, then the floats.
template <std::size_t N>
void format_label(const unsigned char* params, abi::TextSink* out) {
  const char* s = nullptr;
  std::memcpy(&s, params, sizeof s);
  out->write("\"", 1);
  for (const char* c = s ? s : ""; *c; ++c) {
    switch (*c) {
      case '"': out->write("\\\"", 2); break;
      case '\\': out->write("\\\\", 2); break;
      case '\n': out->write("\\n", 2); break;
      case '\t': out->write("\\t", 2); break;
      default:
        if (static_cast<unsigned char>(*c) < 32 || *c == 127) {
          char text[8];
          const unsigned code = static_cast<unsigned char>(*c);
          const int n = std::snprintf(text, sizeof text, "\\%03o", code);
          out->write(text, static_cast<std::size_t>(n));
        } else {
          out->write(c, 1);
        }
    }
  }
  out->write("\"", 1);
  for (std::size_t k = 0; k < N; ++k) write_number(out, ",%g", float_at(params + sizeof s, k));
}

template <std::size_t>
using FloatParam = float;

template <std::size_t... K>
abi::ModuleType float_module_type(const char* name, std::index_sequence<K...>) {
  constexpr auto n = static_cast<std::uint32_t>(sizeof...(K));
  return abi::ModuleType{name, n * 4, &format_floats<n>, n, nullptr, param_fields<FloatParam<K>...>()};
}
template <std::size_t... K>
abi::ModuleType label_module_type(const char* name, std::index_sequence<K...>) {
  constexpr auto n = static_cast<std::uint32_t>(sizeof...(K));
  return abi::ModuleType{name, static_cast<std::uint32_t>(sizeof(const char*)) + n * 4, &format_label<n>, n + 1,
                         nullptr, param_fields<const char*, FloatParam<K>...>()};
}

// A module of N float parameters; cpfg's strings are not read back.
template <std::size_t N>
abi::ModuleType float_module_type(const char* name) {
  return float_module_type(name, std::make_index_sequence<N>{});
}
// @L("format", p1, ...): the text, then N floats.
template <std::size_t N>
abi::ModuleType label_module_type(const char* name) {
  return label_module_type(name, std::make_index_sequence<N>{});
}

}  // namespace sylva::rt::cpfg
