// lpfgall.h precompiled once per build: the translation takes the pragma the
// preprocessor leaves in its place as it takes the header's text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build/model_builder.h"
#include "lang/cpp_generator.h"
#include "lang/lc_parser.h"
#include "lang/token.h"
#include "test_support.h"

namespace sylva {
namespace {

TEST(RuntimePch, ThePragmaOfThePrecompiledLpfgallStandsForItsText) {
  const std::string pragma = "#pragma GCC pch_preprocess \"/somewhere/lpfgall.h.gch\"";
  const lang::Model model = lang::parse_lc(
      lang::tokenize_preprocessed("# 1 \"model.l\"\n" + pragma + "\n# 2 \"model.l\"\nderivation length: 3;\nAxiom: F(1);\n"),
      "model.l");
  const std::string cpp = lang::generate_cpp(model);
  EXPECT_NE(cpp.find(pragma), std::string::npos);
  EXPECT_LT(cpp.find(pragma), cpp.find("sylva_derivation_length"));
}

TEST(RuntimePch, OnlyThePragmaOfLpfgallStandsForIt) {
  for (const char* header : {"lpfgall.h", "other.h"}) {
    bool seen = false;
    lang::tokenize_preprocessed(std::string("# 1 \"model.l\"\n#pragma GCC pch_preprocess \"/somewhere/") + header +
                                    ".gch\"\n# 2 \"model.l\"\nAxiom: F(1);\n",
                                &seen);
    EXPECT_EQ(seen, std::string(header) == "lpfgall.h") << header;
  }
}

TEST(RuntimePch, PrecompilesTheRuntimeWithTheModelsCompiler) {
  const std::string dir = test::make_temp_dir("runtime-pch");
  const std::string output = dir + "/lpfgall.h.gch";
  build::precompile_runtime(output, build::default_runtime_include_dir(), "g++");
  std::ifstream in(output, std::ios::binary);
  std::string magic(4, '\0');
  in.read(magic.data(), 4);
  EXPECT_EQ(magic, "gpch");
  EXPECT_THROW(build::precompile_runtime(dir + "/x.gch", dir + "/no-runtime", "g++"), ModelError);
}

}  // namespace
}  // namespace sylva
