// The registry of module types: names and ids both ways, encoded sizes,
// parameter printing, and what it takes from a model's descriptor.
#include <gtest/gtest.h>

#include <string>

#include "hand_built_model.h"
#include "lstring/module_types.h"
#include "sylva/predefined_ids.h"

namespace sylva::test {
namespace {

void two_halves(const unsigned char*, abi::TextSink* out) { out->write("1,2"); }

TEST(ModuleTypes, NamesIdsAndSizes) {
  const ModuleTypes types({{"A", 8, &two_halves}, {"B", 0}});
  EXPECT_EQ(types.size(), 2u);
  EXPECT_EQ(types.name(0), "A");
  EXPECT_EQ(types.find("B"), ModuleId{1});
  EXPECT_EQ(types.find("C"), std::nullopt);
  EXPECT_EQ(types.encoded_size(0), 8u + 2u);      // [id] parameters [id], one-byte ids
  EXPECT_EQ(types.encoded_sizes()[1], 1u);  // a module without parameters is its id alone
  std::string text = "A(";
  types.format_params(0, nullptr, text);
  EXPECT_EQ(text, "A(1,2");
  types.format_params(1, nullptr, text);  // no printer: nothing
  EXPECT_EQ(text, "A(1,2");
  EXPECT_FALSE(types.cpfg());
}

TEST(ModuleTypes, FromAModelTheEngineSuppliesThePredefinedPrinters) {
  HandBuiltModel model;
  const ModuleId a = model.module("A", 2);
  abi::ModelDescriptor descriptor = model.descriptor();
  // A model may leave the predefined modules' printers to the engine.
  std::vector<abi::ModuleType> modules(descriptor.modules, descriptor.modules + descriptor.module_count);
  modules[rt::mid::F].format_params = nullptr;
  modules[rt::mid::F].parse_params = nullptr;
  descriptor.modules = modules.data();

  const ModuleTypes types = ModuleTypes::from_model(descriptor);
  ASSERT_EQ(types.size(), descriptor.module_count);
  EXPECT_EQ(types.name(rt::mid::SB), "SB");
  EXPECT_EQ(types.find("A"), a);
  EXPECT_EQ(types[a].param_size, 2 * sizeof(float));
  EXPECT_EQ(types[a].param_count, 2u);
  const float f = 2.5f;
  std::string text;
  types.format_params(rt::mid::F, reinterpret_cast<const unsigned char*>(&f), text);
  EXPECT_EQ(text, "2.5");
  ASSERT_TRUE(types.can_read_params(rt::mid::F));
  const std::string saved = "-0.75";
  abi::TextSource in{saved.c_str(), saved.c_str() + saved.size()};
  float read = 0;
  ASSERT_TRUE(types.read_params(rt::mid::F, &in, reinterpret_cast<unsigned char*>(&read)));
  EXPECT_EQ(read, -0.75f);
  EXPECT_FALSE(types.cpfg());

  // A cpfg model's strings are cpfg's: printed, never read back.
  descriptor.flags = abi::kModelCpfg;
  const ModuleTypes cpfg = ModuleTypes::from_model(descriptor);
  EXPECT_TRUE(cpfg.cpfg());
  EXPECT_FALSE(cpfg.can_read_params(rt::mid::F));
  const float third = 1.0f / 3.0f;
  text.clear();
  cpfg.format_params(rt::mid::F, reinterpret_cast<const unsigned char*>(&third), text);
  EXPECT_EQ(text, "0.333333");  // cpfg's %g
}

}  // namespace
}  // namespace sylva::test
