// cpfg's helpers as a compiled cpfg model calls them. Included here so the
// project's warnings check the header too.
#include <sylva/runtime/cpfg_helpers.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace sylva::rt::cpfg {
namespace {

std::string printed(void (*format)(const unsigned char*, abi::TextSink*), const unsigned char* params) {
  std::string text;
  abi::TextSink sink{&text, [](void* self, const char* s, std::size_t n) {
                       static_cast<std::string*>(self)->append(s, n);
                     }};
  format(params, &sink);
  return text;
}

TEST(CpfgHelpers, AnglesAreInDegrees) {
  EXPECT_DOUBLE_EQ(sin(90), 1.0);
  EXPECT_NEAR(cos(60), 0.5, 1e-15);
  EXPECT_NEAR(tan(45), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(asin(1), 90.0);
  EXPECT_DOUBLE_EQ(acos(0), 90.0);
  EXPECT_DOUBLE_EQ(atan(1), 45.0);
  // atan with two arguments takes x first; atan2 takes y first.
  EXPECT_DOUBLE_EQ(atan(0, 1), 90.0);
  EXPECT_DOUBLE_EQ(atan2(1, 0), 90.0);
}

TEST(CpfgHelpers, SignAndPower) {
  EXPECT_EQ(sign(-3.5), -1.0);
  EXPECT_EQ(sign(0), 0.0);
  EXPECT_EQ(sign(2), 1.0);
  EXPECT_EQ(pow(2, 10), 1024.0);
}

TEST(CpfgHelpers, RanDrawsFromCpfgsOwnStream) {
  random = Random{};
  // erand48 from {0x330E, 0, 0}: (0x5DEECE66D * 0x330E + 0xB) mod 2^48 over 2^48.
  EXPECT_DOUBLE_EQ(ran(10), 1.7082803610628972);
  EXPECT_DOUBLE_EQ(ran(1), 0.7499019804849638);
  // srand(0) restarts at {0x330E, 0, 0}, where the stream began.
  EXPECT_EQ(srand(0), 0.0);
  EXPECT_DOUBLE_EQ(ran(1), 0.17082803610628972);
}

TEST(CpfgHelpers, FloatsPrintAsPercentG) {
  const float values[] = {1.5f, -2.0f, 0.1f};
  EXPECT_EQ(printed(&format_floats<3>, reinterpret_cast<const unsigned char*>(values)), "1.5,-2,0.1");
}

TEST(CpfgHelpers, LabelPrintsItsTextWithCEscapes) {
  struct {
    const char* text;
    float value;
  } label{"a\"b\\c\nd\x01", 3.25f};
  unsigned char params[sizeof(const char*) + sizeof(float)];
  std::memcpy(params, &label.text, sizeof label.text);
  std::memcpy(params + sizeof label.text, &label.value, sizeof label.value);
  EXPECT_EQ(printed(&format_label<1>, params), "\"a\\\"b\\\\c\\nd\\001\",3.25");
}

TEST(CpfgHelpers, ModuleTypesDescribeTheirFloats) {
  const abi::ModuleType plain = float_module_type<3>("X");
  EXPECT_EQ(plain.param_size, 12u);
  ASSERT_EQ(plain.param_count, 3u);
  for (std::uint32_t k = 0; k < 3; ++k) {
    EXPECT_EQ(plain.params[k].offset, 4 * k);
    EXPECT_EQ(plain.params[k].type->kind, abi::ParamKind::kFloat);
  }
  EXPECT_EQ(plain.parse_params, nullptr);

  const abi::ModuleType label = label_module_type<2>("@L");
  EXPECT_EQ(label.param_size, sizeof(const char*) + 8);
  ASSERT_EQ(label.param_count, 3u);
  EXPECT_EQ(label.params[0].type->kind, abi::ParamKind::kText);
  EXPECT_EQ(label.params[1].offset, sizeof(const char*));
  EXPECT_EQ(label.params[2].type->kind, abi::ParamKind::kFloat);
}

TEST(CpfgHelpers, FilesAreNumberedFromOne) {
  const std::string path = (std::filesystem::temp_directory_path() / "sylva_cpfg_helpers_test.txt").string();
  const double id = fopen(path.c_str(), "w");
  ASSERT_EQ(id, 1.0);
  EXPECT_EQ(fprintf(id, "%g %g\n", 1.5, 2.0), 6.0);  // "1.5 2\n"
  EXPECT_EQ(fclose(id), 0.0);
  EXPECT_EQ(file(id), nullptr);
  EXPECT_EQ(fclose(id), -1.0);  // already closed

  const double again = fopen(path.c_str(), "r");
  ASSERT_EQ(again, 1.0);
  float a = 0, b = 0;
  EXPECT_EQ(fscan(again, "%f %f", &a, &b), 2.0);
  EXPECT_EQ(a, 1.5f);
  EXPECT_EQ(b, 2.0f);
  fclose(again);
  std::filesystem::remove(path);
}

TEST(CpfgHelpers, AFileThatCannotBeOpenedIsZeroAndSaysSo) {
  std::string said;
  control.host = &said;
  control.message = [](void* host, const char* text) { *static_cast<std::string*>(host) += text; };
  EXPECT_EQ(fopen("/nonexistent-directory/file", "r"), 0.0);
  EXPECT_EQ(said, "fopen: cannot open /nonexistent-directory/file\n");
  control.message = nullptr;
  control.host = nullptr;
}

}  // namespace
}  // namespace sylva::rt::cpfg
