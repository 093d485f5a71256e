// Reading the text form of a string back: typed parameters by module name,
// and errors at the line and column of the saved text.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/string_reader.h"
#include "support/diagnostic.h"
#include "sylva/runtime/modules.h"

namespace sylva::io {
namespace {

ModuleTypes test_types() {
  auto entry = [](const abi::ModuleType& t) {
    return ModuleTypes::Type{t.name, t.param_size, t.format_params, t.param_count, t.parse_params, t.params};
  };
  return ModuleTypes({entry(rt::module_type<float, int, V3f, bool, double>("A")), entry(rt::module_type<>("B")),
                      entry(rt::module_type<V2d, unsigned char, float[2]>("C"))});
}

template <class T>
T param_at(const ModuleString& s, std::size_t offset) {
  T value;
  std::memcpy(static_cast<void*>(&value), s.data() + offset, sizeof value);
  return value;
}

TEST(StringReader, ReadsEveryParameterWithItsType) {
  const ModuleTypes types = test_types();
  const ModuleString s =
      parse_string("A(0.100000001,-3,(1,2.5,-0.25),1,0.33333333333333331)  B\n\tC((0.5,-2),255,[3,4])\n", types, "s");
  ASSERT_EQ(s.count_modules(types), 3u);
  // A: [id] float int V3f bool double [id], one-byte ids
  std::size_t at = 1;
  EXPECT_EQ(param_at<float>(s, at), 0.1f);
  EXPECT_EQ(param_at<int>(s, at + 4), -3);
  const V3f v = param_at<V3f>(s, at + 8);
  EXPECT_EQ(v.x, 1.0f);
  EXPECT_EQ(v.y, 2.5f);
  EXPECT_EQ(v.z, -0.25f);
  EXPECT_TRUE(param_at<bool>(s, at + 20));
  EXPECT_EQ(param_at<double>(s, at + 21), 1.0 / 3.0);
  at += types[0].param_size + 1;
  EXPECT_EQ(module_id_at(s.data(), at), 1);  // B: [id]
  at += types.encoded_size(1) + 1;
  const V2d w = param_at<V2d>(s, at);
  EXPECT_EQ(w.x, 0.5);
  EXPECT_EQ(w.y, -2.0);
  EXPECT_EQ(param_at<unsigned char>(s, at + 16), 255);
  EXPECT_EQ(param_at<float>(s, at + 17), 3.0f);
  EXPECT_EQ(param_at<float>(s, at + 21), 4.0f);
}

TEST(StringReader, AnEmptyTextIsAnEmptyString) {
  EXPECT_TRUE(parse_string(" \n", test_types(), "s").empty());
}

std::string error_of(const std::string& text) {
  try {
    parse_string(text, test_types(), "saved.str");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StringReader, ErrorsPointIntoTheSavedText) {
  EXPECT_EQ(error_of("B\nB D"), "saved.str:2:3: error: unknown module 'D' (the model declares no module of that name)");
  EXPECT_EQ(error_of("B(1)"), "saved.str:1:1: error: module 'B' has 0 parameters but the saved string gives 1");
  EXPECT_EQ(error_of("C((1,2),256,[1,2])"),
            "saved.str:1:9: error: expected an integer in the range of the parameter's type in the parameters of 'C'");
  EXPECT_EQ(error_of("C((1,2),-1,[1,2])"), "saved.str:1:9: error: expected an integer of 0 or more in the parameters of 'C'");
  EXPECT_EQ(error_of("C((1,2)x,1,[1,2])"), "saved.str:1:8: error: expected ',' in the parameters of 'C'");
  EXPECT_EQ(error_of("A(1,2,(1,2,3),1,4)B"), "saved.str:1:19: error: expected a space between modules, found 'B'");
  EXPECT_EQ(error_of("B A(1,2"), "saved.str:1:4: error: expected ')' to close the parameters of 'A'");
}

// ---- struct fields: every field once --------------------------------------

ModuleTypes mouse_types() {
  const abi::ModuleType t = rt::module_type<MouseStatus>("M");
  return ModuleTypes({ModuleTypes::Type{t.name, t.param_size, t.format_params, t.param_count, t.parse_params}});
}

std::string mouse_error_of(const std::string& text) {
  try {
    parse_string(text, mouse_types(), "saved.str");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kAllMouseFields =
    "viewNum=1,viewX=2,viewY=3,atFront=(0,0,0),atRear=(0,0,0),atMiddle=(0,0,0),selectDepth=0.5,"
    "selectPoint=(1,2,3),keypressed=0,lbDown=0,lbPushed=1,lbReleased=0";

TEST(StringReader, AStructWithAllItsFieldsReadsBack) {
  const ModuleString s = parse_string("M({" + kAllMouseFields + "})", mouse_types(), "s");
  const MouseStatus m = param_at<MouseStatus>(s, 1);  // past a one-byte id
  EXPECT_EQ(m.viewY, 3);
  EXPECT_EQ(m.selectPoint.y, 2);
  EXPECT_TRUE(m.lbPushed);
}

TEST(StringReader, AStructFieldLeftOutIsAnErrorAtTheClosingBrace) {
  // M({viewNum=1}): the '}' is column 13; viewX is the first field not given.
  EXPECT_EQ(mouse_error_of("M({viewNum=1})"),
            "saved.str:1:13: error: expected field 'viewX' (a saved struct gives all its fields) in the parameters of "
            "'M'");
  EXPECT_EQ(mouse_error_of("M({})"),
            "saved.str:1:4: error: expected field 'viewNum' (a saved struct gives all its fields) in the parameters of "
            "'M'");
  // Fields in another order are still all there.
  EXPECT_EQ(mouse_error_of("M({lbReleased=0,viewNum=1,viewX=2,viewY=3,atFront=(0,0,0),atRear=(0,0,0),"
                           "atMiddle=(0,0,0),selectDepth=0,selectPoint=(0,0,0),keypressed=0,lbDown=0,lbPushed=1})"),
            "no error");
}

TEST(StringReader, AStructFieldGivenTwiceIsAnErrorAtItsSecondName) {
  // "M({" is columns 1-3, "viewNum=1," 4-13: the second viewNum is at 14.
  EXPECT_EQ(mouse_error_of("M({viewNum=1,viewNum=2," + kAllMouseFields.substr(10) + "})"),
            "saved.str:1:14: error: expected field 'viewNum' only once in the parameters of 'M'");
}

// ---- files ------------------------------------------------------------------

std::string file_error_of(const std::string& path) {
  try {
    read_string_file(path, test_types());
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StringReader, ADirectoryIsNoSavedString) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sylva-string-reader-dir";
  std::filesystem::create_directories(dir);
  EXPECT_EQ(file_error_of(dir.string()),
            dir.string() + ": error: cannot read the saved string: it is a directory, not a file");
}

TEST(StringReader, AnEmptyFileIsAnErrorAndALineWithoutModulesIsTheEmptyString) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sylva-string-reader-files";
  std::filesystem::create_directories(dir);
  const std::string empty = (dir / "empty.str").string(), blank = (dir / "blank.str").string();
  std::ofstream(empty, std::ios::binary).flush();
  std::ofstream(blank, std::ios::binary) << "\n";  // what OutputString writes for a string of no modules
  EXPECT_EQ(file_error_of(empty), empty +
                                      ": error: cannot read the saved string: the file is empty (a saved string, "
                                      "even one of no modules, is a line)");
  EXPECT_TRUE(read_string_file(blank, test_types()).empty());
}

}  // namespace
}  // namespace sylva::io
