// The model ABI's description of parameters (abi::ParamType), and the
// registry's typed access to them.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "lstring/module_types.h"
#include "sylva/runtime/modules.h"

namespace {

// A struct of a model, described as the translator describes one.
struct Leaf {
  int age;
  double length;
  V2f tip;
  char name[4];
  unsigned bits : 3;
};

template <class S>
  requires std::is_same_v<S, Leaf>
sylva::rt::FieldList sylva_struct_fields(const S*) {
  static const sylva::abi::ParamField fields[] = {
      sylva::rt::param_field<decltype(S::age)>("age", __builtin_offsetof(S, age)),
      sylva::rt::param_field<decltype(S::length)>("length", __builtin_offsetof(S, length)),
      sylva::rt::param_field<decltype(S::tip)>("tip", __builtin_offsetof(S, tip)),
      sylva::rt::param_field<decltype(S::name)>("name", __builtin_offsetof(S, name)),
      sylva::abi::ParamField{"bits", 0, nullptr},
  };
  return {fields, 5};
}

enum class Stage : short { Bud = 1, Flower = 7 };

}  // namespace

namespace sylva {
namespace {

using abi::ParamKind;

TEST(ParamTypes, ModuleParametersLieInOrderWithoutPadding) {
  const abi::ModuleType t = rt::module_type<float, int, V3f, bool, double>("A");
  ASSERT_EQ(t.param_count, 5u);
  const std::uint32_t offsets[] = {0, 4, 8, 20, 21};
  const ParamKind kinds[] = {ParamKind::kFloat, ParamKind::kSigned, ParamKind::kVector, ParamKind::kBool,
                             ParamKind::kDouble};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(t.params[k].offset, offsets[k]) << k;
    EXPECT_EQ(t.params[k].type->kind, kinds[k]) << k;
    EXPECT_EQ(t.params[k].name, nullptr);
  }
  const abi::ParamType& v = *t.params[2].type;
  EXPECT_EQ(v.size, 12u);
  EXPECT_EQ(v.count, 3u);
  EXPECT_EQ(v.element->kind, ParamKind::kFloat);
  EXPECT_EQ(rt::module_type<>("B").params, nullptr);
}

TEST(ParamTypes, IntegersEnumsArraysAndText) {
  EXPECT_EQ(rt::param_type<unsigned char>()->kind, ParamKind::kUnsigned);
  EXPECT_EQ(rt::param_type<unsigned char>()->size, 1u);
  EXPECT_EQ(rt::param_type<long>()->kind, ParamKind::kSigned);
  const abi::ParamType& stage = *rt::param_type<Stage>();
  EXPECT_EQ(stage.kind, ParamKind::kEnum);
  EXPECT_EQ(stage.element->kind, ParamKind::kSigned);
  EXPECT_EQ(stage.element->size, 2u);
  const abi::ParamType& array = *rt::param_type<float[2][3]>();
  EXPECT_EQ(array.kind, ParamKind::kArray);
  EXPECT_EQ(array.count, 2u);
  EXPECT_EQ(array.element->kind, ParamKind::kArray);
  EXPECT_EQ(array.element->size, 12u);
  EXPECT_EQ(rt::param_type<const char*>()->kind, ParamKind::kText);
  EXPECT_EQ(rt::param_type<int*>()->kind, ParamKind::kOther);
}

TEST(ParamTypes, StructsListTheirFields) {
  const abi::ParamType& leaf = *rt::param_type<Leaf>();
  ASSERT_EQ(leaf.kind, ParamKind::kStruct);
  ASSERT_EQ(leaf.field_count, 5u);
  EXPECT_STREQ(leaf.fields[1].name, "length");
  EXPECT_EQ(leaf.fields[1].offset, offsetof(Leaf, length));
  EXPECT_EQ(leaf.fields[2].type->kind, ParamKind::kVector);
  EXPECT_EQ(leaf.fields[4].type, nullptr);  // a bit-field has no place

  const abi::ParamType& mouse = *rt::param_type<MouseStatus>();
  ASSERT_EQ(mouse.field_count, 12u);
  EXPECT_STREQ(mouse.fields[0].name, "viewNum");
  EXPECT_STREQ(mouse.fields[11].name, "lbReleased");
  // A struct whose fields nothing lists.
  EXPECT_EQ(rt::param_type<TabletStatus>()->kind, ParamKind::kStruct);
  EXPECT_EQ(rt::param_type<TabletStatus>()->field_count, 0u);
}

ModuleTypes types_of(const abi::ModuleType& t) {
  return ModuleTypes(
      {ModuleTypes::Type{t.name, t.param_size, t.format_params, t.param_count, t.parse_params, t.params}});
}

template <class... T>
std::vector<unsigned char> block(const T&... values) {
  std::vector<unsigned char> bytes;
  (bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&values),
                reinterpret_cast<const unsigned char*>(&values) + sizeof values),
   ...);
  return bytes;
}

TEST(ModuleTypesNumbers, NumbersInDeclarationOrder) {
  const ModuleTypes types = types_of(rt::module_type<float, int, V3d, bool, const char*, Stage, unsigned char>("A"));
  const char* text = "label";
  const std::vector<unsigned char> params =
      block(1.5f, -3, V3d(0.25, 2, -1), true, text, Stage::Flower, static_cast<unsigned char>(200));
  EXPECT_EQ(types.numbers(0, params.data()), (std::vector<double>{1.5, -3, 0.25, 2, -1, 1, 7, 200}));
  EXPECT_EQ(types.params(0).size(), 7u);
}

TEST(ModuleTypesNumbers, StructsGiveTheirKnownFields) {
  const ModuleTypes types = types_of(rt::module_type<Leaf, EA20Array>("L"));
  Leaf leaf{4, 0.5, V2f(1, 2), {'a', 'b', 'c', 0}, 5};
  EA20Array ea{};
  for (int k = 0; k < 20; ++k) ea[k] = static_cast<float>(k);
  const std::vector<unsigned char> params = block(leaf, ea);
  std::vector<double> expected = {4, 0.5, 1, 2, 'a', 'b', 'c', 0};
  for (int k = 0; k < 20; ++k) expected.push_back(k);
  EXPECT_EQ(types.numbers(0, params.data()), expected);
}

TEST(ModuleTypesNumbers, TypesBuiltByHandHaveNone) {
  const ModuleTypes types({ModuleTypes::Type{"F", 4, nullptr}});
  const float length = 2;
  EXPECT_TRUE(types.params(0).empty());
  EXPECT_TRUE(types.numbers(0, reinterpret_cast<const unsigned char*>(&length)).empty());
}

}  // namespace
}  // namespace sylva
