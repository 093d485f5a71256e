// The types of modules' parameters as the model ABI describes them
// (abi::ParamType): what each parameter is and where it lies, so the engine
// reads parameters directly. Included by modules.h.
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/types.h>
#include <sylva/runtime/vectors.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace sylva::rt {

// A struct's fields as its describer lists them (sylva_struct_fields).
struct FieldList {
  const abi::ParamField* fields;
  std::uint32_t count;
  const char* name = nullptr;  // the struct's
};

template <class T>
const abi::ParamType* param_type();

template <class T>
abi::ParamType describe_param() {
  using abi::ParamKind;
  constexpr auto size = static_cast<std::uint32_t>(sizeof(T));
  if constexpr (std::is_same_v<T, float>) {
    return {ParamKind::kFloat, size};
  } else if constexpr (std::is_same_v<T, double>) {
    return {ParamKind::kDouble, size};
  } else if constexpr (std::is_same_v<T, long double>) {
    return {ParamKind::kLongDouble, size};
  } else if constexpr (std::is_same_v<T, bool>) {
    return {ParamKind::kBool, size};
  } else if constexpr (std::is_enum_v<T>) {
    return {ParamKind::kEnum, size, param_type<std::underlying_type_t<T>>()};
  } else if constexpr (std::is_integral_v<T>) {
    return {std::is_signed_v<T> ? ParamKind::kSigned : ParamKind::kUnsigned, size};
  } else if constexpr (vector_size<T> > 0) {
    return {ParamKind::kVector, size, param_type<std::remove_cv_t<decltype(T::x)>>(),
            static_cast<std::uint32_t>(vector_size<T>)};
  } else if constexpr (std::is_same_v<T, const char*> || std::is_same_v<T, char*>) {
    return {ParamKind::kText, size};
  } else if constexpr (std::is_array_v<T>) {
    return {ParamKind::kArray, size, param_type<std::remove_cv_t<std::remove_extent_t<T>>>(),
            static_cast<std::uint32_t>(std::extent_v<T>)};
  } else if constexpr (requires(const T* p) { sylva_struct_fields(p); }) {
    // Structs of the model: the translator writes these overloads.
    const FieldList fields = sylva_struct_fields(static_cast<const T*>(nullptr));
    return {ParamKind::kStruct, size, nullptr, 0, fields.fields, fields.count, fields.name};
  } else if constexpr (std::is_class_v<T>) {
    return {ParamKind::kStruct, size};
  } else {
    return {ParamKind::kOther, size};
  }
}

template <class T>
const abi::ParamType* param_type() {
  static const abi::ParamType type = describe_param<std::remove_cv_t<T>>();
  return &type;
}

// A module's parameters of types T..., packed in order from offset 0.
template <class... T>
const abi::ParamField* param_fields() {
  if constexpr (sizeof...(T) == 0) {
    return nullptr;
  } else {
    static const std::array<abi::ParamField, sizeof...(T)> fields = [] {
      std::array<abi::ParamField, sizeof...(T)> list{};
      std::uint32_t offset = 0;
      std::size_t k = 0;
      ((list[k++] = abi::ParamField{nullptr, offset, param_type<T>()}, offset += sizeof(T)), ...);
      return list;
    }();
    return fields.data();
  }
}

// Whether the engine writes a value of type T as text from its table
// (the engine's lstring/param_text.h), so that a model need not compile a
// printer for it. The model's structs say so through
// sylva_struct_text_from_table, which the translator writes.
template <class T>
constexpr bool text_from_table() {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    return true;
  } else if constexpr (vector_size<T> > 0) {
    return text_from_table<std::remove_cv_t<decltype(T::x)>>();
  } else if constexpr (std::is_same_v<T, const char*> || std::is_same_v<T, char*>) {
    return true;
  } else if constexpr (std::is_array_v<T>) {
    return text_from_table<std::remove_cv_t<std::remove_extent_t<T>>>();
  } else if constexpr (requires(const T* p) { sylva_struct_text_from_table(p); }) {
    return sylva_struct_text_from_table(static_cast<const T*>(nullptr));
  } else {
    return false;
  }
}

// A field of type F at `offset` in its struct.
template <class F>
abi::ParamField param_field(const char* name, std::size_t offset) {
  return abi::ParamField{name, static_cast<std::uint32_t>(offset), param_type<F>()};
}

}  // namespace sylva::rt

// The predefined types' fields, as modules.h prints them.
#define SYLVA_FIELD(S, f) ::sylva::rt::param_field<decltype(S::f)>(#f, offsetof(S, f))

inline sylva::rt::FieldList sylva_struct_fields(const EA20Array*) {
  static const sylva::abi::ParamField fields[] = {SYLVA_FIELD(EA20Array, data)};
  return {fields, 1, "EA20Array"};
}
inline sylva::rt::FieldList sylva_struct_fields(const SurfaceObj*) {
  static const sylva::abi::ParamField fields[] = {SYLVA_FIELD(SurfaceObj, points)};
  return {fields, 1, "SurfaceObj"};
}
inline sylva::rt::FieldList sylva_struct_fields(const MouseStatus*) {
  static const sylva::abi::ParamField fields[] = {
      SYLVA_FIELD(MouseStatus, viewNum),     SYLVA_FIELD(MouseStatus, viewX),    SYLVA_FIELD(MouseStatus, viewY),
      SYLVA_FIELD(MouseStatus, atFront),     SYLVA_FIELD(MouseStatus, atRear),   SYLVA_FIELD(MouseStatus, atMiddle),
      SYLVA_FIELD(MouseStatus, selectDepth), SYLVA_FIELD(MouseStatus, selectPoint),
      SYLVA_FIELD(MouseStatus, keypressed),  SYLVA_FIELD(MouseStatus, lbPushed), SYLVA_FIELD(MouseStatus, lbDown),
      SYLVA_FIELD(MouseStatus, lbReleased)};
  return {fields, 12, "MouseStatus"};
}
inline sylva::rt::FieldList sylva_struct_fields(const CameraPosition*) {
  static const sylva::abi::ParamField fields[] = {
      SYLVA_FIELD(CameraPosition, position), SYLVA_FIELD(CameraPosition, lookat), SYLVA_FIELD(CameraPosition, head),
      SYLVA_FIELD(CameraPosition, left),     SYLVA_FIELD(CameraPosition, up),     SYLVA_FIELD(CameraPosition, scale)};
  return {fields, 6, "CameraPosition"};
}

#undef SYLVA_FIELD
