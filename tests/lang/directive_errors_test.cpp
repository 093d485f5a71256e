// An error in a preprocessor directive of a model or of an input file names
// the file, the line and the column: FILE:LINE:COL: error: ...
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "build/model_builder.h"
#include "inputs/view_file.h"
#include "lang/translator.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {

struct Directive {
  std::string name;
  std::string line;    // the directive, written on line 2
  std::string prefix;  // ":2:COL: error: " after the file's name
  std::string what;
};

const Directive kDirectives[] = {
    {"MissingInclude", "#include \"missing.h\"", ":2:10: error: ", "missing.h: No such file or directory"},
    {"IfWithoutOperand", "#if 1 +\n#endif", ":2:8: error: ", "operator '+' has no right operand"},
    {"Error", "#error stop here", ":2:2: error: ", "#error stop here"},
    {"UnterminatedIf", "#if 1", ":2:1: error: ", "unterminated #if"},
};

std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir + "/" + name) << text;
  return dir + "/" + name;
}

class DirectiveErrors : public ::testing::TestWithParam<Directive> {};

TEST_P(DirectiveErrors, InAnLcModel) {
  const Directive& d = GetParam();
  const std::string path = write(make_temp_dir("directive-lc-" + d.name), "model.l",
                                 "module A(float);\n" + d.line + "\naxiom: A(1);\n");
  lang::TranslatorOptions options;
  options.compiler = default_compiler();
  options.runtime_include_dir = build::default_runtime_include_dir();
  EXPECT_EQ(error_of([&] { lang::translate_file(path, options); }), path + d.prefix + d.what);
}

TEST_P(DirectiveErrors, InACpfgModel) {
  const Directive& d = GetParam();
  const std::string path = write(make_temp_dir("directive-cpfg-" + d.name), "model.l",
                                 "Lsystem: 1\n" + d.line + "\nAxiom: F\nendlsystem\n");
  lang::TranslatorOptions options;
  options.compiler = default_compiler();
  options.runtime_include_dir = build::default_runtime_include_dir();
  EXPECT_EQ(error_of([&] { lang::translate_file(path, options); }), path + d.prefix + d.what);
}

TEST_P(DirectiveErrors, InAViewFile) {
  const Directive& d = GetParam();
  const std::string path = write(make_temp_dir("directive-view-" + d.name), "view.v", "scale: 1\n" + d.line + "\n");
  EXPECT_EQ(error_of([&] { io::read_view_file(path); }), path + d.prefix + d.what);
}

INSTANTIATE_TEST_SUITE_P(Table, DirectiveErrors, ::testing::ValuesIn(kDirectives),
                         [](const ::testing::TestParamInfo<Directive>& info) { return info.param.name; });

}  // namespace
}  // namespace sylva::test
