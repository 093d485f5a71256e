// The C++ a cpfg model is translated into compiles without a warning under
// the project's warnings, runtime helpers included.
#include <gtest/gtest.h>

#include <fstream>

#include "build/model_builder.h"
#include "lang/translator.h"
#include "support/default_compiler.h"
#include "support/subprocess.h"
#include "test_support.h"

namespace sylva::test {
namespace {

void expect_no_warnings(const std::string& model) {
  SCOPED_TRACE(model);
  lang::TranslatorOptions options;
  options.compiler = default_compiler();
  options.runtime_include_dir = build::default_runtime_include_dir();
  const lang::Translation translation = lang::translate_file(model, options);
  const std::string cpp = make_temp_dir("cpfg-generated-code") + "/model.ii";
  std::ofstream(cpp) << translation.cpp;
  const ProcessResult result =
      run_process({options.compiler, "-std=gnu++20", "-fsyntax-only", "-Wall", "-Wextra", "-Werror", "-x", "c++", cpp});
  EXPECT_EQ(result.exit_code, 0) << result.err;
}

// Stochastic productions, a homomorphism, and a communication module with
// random numbers: the parts of the generated code that differ most.
TEST(CpfgGeneratedCode, CompilesWithoutWarnings) {
  expect_no_warnings(example_path("cpfg/manual-stochastic/manual-stochastic.l"));
  expect_no_warnings(example_path("cpfg/manual-homomorphism/manual-homomorphism.l"));
  expect_no_warnings(example_path("cpfg/light-competition-tree/light-competition-tree.l"));
}

}  // namespace
}  // namespace sylva::test
