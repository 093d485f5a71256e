// cpfg golden tests: the strings the real cpfg (vlab 5.1) derived from the cpfg
// models in tests/golden-cpfg (copied from the reference set; see
// tests/golden-cpfg/*/README.md and CPFG-INDEX.md of the reference set).
//
// Every folder holds lsystem.l, expected-stepN.txt (cpfg's string after N
// steps) and, for models with a homomorphism, expected-homo-stepN.txt (the
// string after the homomorphism). The strings must be equal byte for byte.
// Also: recognising cpfg files, --lang, and errors in bad cpfg input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "build/model_builder.h"
#include "io/string_text.h"
#include "lang/translator.h"
#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

struct CpfgCase {
  std::string folder;
  int steps = 0;
  bool homomorphism = false;  // expected-homo-stepN.txt
};

void PrintTo(const CpfgCase& c, std::ostream* os) {
  *os << c.folder << (c.homomorphism ? " homomorphism" : "") << " step " << c.steps;
}

std::string cpfg_dir() { return data_path("golden-cpfg"); }

std::vector<CpfgCase> find_cases() {
  std::vector<CpfgCase> cases;
  const std::regex re(R"(expected-(homo-)?step(\d+)\.txt)");
  const std::vector<fs::path> folders = model_folders(cpfg_dir());
  for (const fs::path& folder : folders) {
    std::vector<CpfgCase> found;
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      std::smatch m;
      if (std::regex_match(name, m, re)) found.push_back({folder.filename().string(), std::stoi(m[2].str()), m[1].matched});
    }
    std::sort(found.begin(), found.end(), [](const CpfgCase& a, const CpfgCase& b) {
      return std::tie(a.homomorphism, a.steps) < std::tie(b.homomorphism, b.steps);
    });
    cases.insert(cases.end(), found.begin(), found.end());
  }
  return cases;
}

std::string case_name(const testing::TestParamInfo<CpfgCase>& info) {
  std::string name = info.param.folder + (info.param.homomorphism ? "_homo" : "") + "_step" +
                     std::to_string(info.param.steps);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

std::string without_final_newline(std::string s) {
  if (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

std::string first_difference(const std::string& expected, const std::string& actual) {
  std::size_t i = 0;
  while (i < expected.size() && i < actual.size() && expected[i] == actual[i]) ++i;
  auto around = [i](const std::string& s) { return s.substr(i >= 40 ? i - 40 : 0, 80); };
  return "expected " + std::to_string(expected.size()) + " bytes, got " + std::to_string(actual.size()) +
         "; first difference at byte " + std::to_string(i) + ":\n  expected: ..." + around(expected) +
         "\n  actual:   ..." + around(actual);
}

class CpfgGolden : public testing::TestWithParam<CpfgCase> {};

TEST_P(CpfgGolden, MatchesCpfg) {
  const CpfgCase& c = GetParam();
  const fs::path folder = fs::path(cpfg_dir()) / c.folder;
  const std::string expected = without_final_newline(read_text(
      (folder / ((c.homomorphism ? "expected-homo-step" : "expected-step") + std::to_string(c.steps) + ".txt")).string()));
  ASSERT_FALSE(expected.empty());
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  // These strings follow cpfg's window in seeding drand48 from seed:
  // (CPFG-INDEX.md); its batch runs do not.
  options.cpfg_window_seeding = true;
  Simulation simulation((folder / "lsystem.l").string(), options);
  simulation.run(c.steps);
  const std::string actual = without_final_newline(
      c.homomorphism ? io::format_string(simulation.interpreted(0), simulation.types())
                     : io::format_string(simulation.string(), simulation.types()));
  EXPECT_TRUE(actual == expected) << c.folder << " after " << c.steps << " steps:\n" << first_difference(expected, actual);
}

INSTANTIATE_TEST_SUITE_P(golden_cpfg, CpfgGolden, testing::ValuesIn(find_cases()), case_name);

TEST(CpfgGoldenSet, all_folders_present) {
  std::size_t folders = 0;
  for (const auto& entry : fs::directory_iterator(cpfg_dir()))
    if (entry.is_directory()) ++folders;
  EXPECT_EQ(folders, 36u);
  EXPECT_GE(find_cases().size(), 150u);
}

// ---- recognition and errors ------------------------------------------------------

std::string write_model(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = (fs::path(dir) / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(CpfgRecognition, lsystem_and_endlsystem_lines_make_cpfg) {
  EXPECT_TRUE(lang::looks_like_cpfg("/* cpfg */\nLsystem: 1\nAxiom: A\nA --> AB\nendlsystem\n"));
  EXPECT_TRUE(lang::looks_like_cpfg("lsystem: 1\n  axiom: A\nendlsystem"));
  EXPECT_FALSE(lang::looks_like_cpfg("/*\nLsystem: 1\nendlsystem\n*/\nmodule A();\n"));
  EXPECT_FALSE(lang::looks_like_cpfg("#include <lpfgall.h>\nderivation length: 2;\nAxiom: A;\n"));
  EXPECT_FALSE(lang::looks_like_cpfg("// Lsystem: 1\n// endlsystem\n"));
}

TEST(CpfgRecognition, runs_and_lang_override) {
  const std::string dir = make_temp_dir("cpfg-lang");
  const std::string model =
      write_model(dir, "m.txt", "#define N 2\nLsystem: 1\nderivation length: N\nAxiom: F(1)\nF(x) --> F(x/2)[+F(x/3)]\nendlsystem\n");
  ProcessResult r = run_sylva({"run", model});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "F(0.25)[+F(0.166667)][+F(0.166667)[+F(0.111111)]]\n");
  r = run_sylva({"run", model, "--lang", "cpfg", "--steps", "1"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "F(0.5)[+F(0.333333)]\n");
  r = run_sylva({"run", model, "--lang", "lc"});  // read as L+C it is not valid
  EXPECT_NE(r.exit_code, 0);
  r = run_sylva({"run", model, "--lang", "pascal"});
  EXPECT_NE(r.exit_code, 0);
  fs::remove_all(dir);
}

// Runs a bad model; returns stderr, expecting a failure.
std::string error_of(const std::string& text) {
  const std::string dir = make_temp_dir("cpfg-error");
  const std::string model = write_model(dir, "bad.l", text);
  const ProcessResult r = run_sylva({"run", model});
  EXPECT_NE(r.exit_code, 0) << "the model was accepted:\n" << text;
  fs::remove_all(dir);
  return r.err;
}

TEST(CpfgErrors, syntax_error_points_at_the_place) {
  const std::string err = error_of("Lsystem: 1\nAxiom: A\nA(x) : x > --> B\nendlsystem\n");
  EXPECT_NE(err.find("bad.l:3:"), std::string::npos) << err;
  EXPECT_NE(err.find("expected an expression"), std::string::npos) << err;
}

TEST(CpfgErrors, missing_arrow) {
  const std::string err = error_of("Lsystem: 1\nAxiom: A\nA B C\nendlsystem\n");
  EXPECT_NE(err.find("bad.l:3:"), std::string::npos) << err;
  EXPECT_NE(err.find("expected '-->'"), std::string::npos) << err;
}

TEST(CpfgErrors, no_symbol_where_a_module_is_expected) {
  const std::string err = error_of("Lsystem: 1\nAxiom: A(1)\nA(x) --> B((x)\nendlsystem\n");
  EXPECT_NE(err.find("bad.l:3:"), std::string::npos) << err;
  const std::string err2 = error_of("Lsystem: 1\nAxiom: A(1)\n(x) --> B\nendlsystem\n");
  EXPECT_NE(err2.find("bad.l:3:1: error: expected a symbol"), std::string::npos) << err2;
}

// An unknown name and a probability that is a name are not errors in cpfg
// (it warns and reads 0): see cpfg_dialect_test.cpp.

TEST(CpfgErrors, sub_lsystem_errors) {
  const std::string err = error_of("Lsystem: 1\nAxiom: A(1)\nA(t) --> ?(2,1)B(t-1)$\nendlsystem\n");
  EXPECT_NE(err.find("bad.l:3:12: error: ?(2,...) calls L-system 2, but no 'Lsystem: 2' is defined"), std::string::npos)
      << err;
  const std::string err2 = error_of("Lsystem: 1\nAxiom: A\nendlsystem\nA --> B\n");
  EXPECT_NE(err2.find("bad.l:4:1: error: expected 'Lsystem:' (a sub-L-system) after 'endlsystem'"), std::string::npos)
      << err2;
}

TEST(CpfgErrors, missing_endlsystem_with_lang_cpfg) {
  const std::string dir = make_temp_dir("cpfg-noend");
  const std::string model = write_model(dir, "m.l", "Lsystem: 1\nAxiom: A\nA --> AB\n");
  const ProcessResult r = run_sylva({"run", model, "--lang", "cpfg"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("endlsystem"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva::test
