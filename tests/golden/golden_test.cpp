// Golden tests: the strings the real lpfg derived from the L+C models in
// tests/golden (copied from the reference set, see tests/golden/*/README.md).
//
// Every folder tests/golden/<name>/ holds lsystem.l and expected-stepN.txt, the
// string lpfg printed after N steps. One test case per (folder, N), found by
// scanning tests/golden when the test program starts. The engine must match
// lpfg exactly: module names, structure and the value of every number.
//
// Files other than lsystem.l, README.md and expected-* in a folder are inputs
// the model reads from its working directory (notes-circuit-solver reads
// circuit-1.dat), and expected-stepN.<file> other than .txt is a file the model
// itself writes there (thesis-L30-control-statements writes output.dat). Such
// models run through the sylva program in a temporary copy of the folder;
// the others are derived in-process, which is faster.
//
// The reference strings print a float with %.9g and a double with %.17g;
// Sylva prints each in its shortest exact form. Numbers are therefore
// compared as the values they read back to (same_text below), everything
// else character by character.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

struct GoldenCase {
  std::string folder;                     // e.g. thesis-L26-branching
  int steps = 0;                          // N of expected-stepN.txt
  std::vector<std::string> written;       // files the model writes, compared after N steps
  bool needs_working_dir = false;         // reads inputs or writes files
};

// Shown by gtest (and in ctest's test names) instead of the object's bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.folder << " step " << c.steps; }

std::string golden_dir() { return data_path("golden"); }

std::vector<GoldenCase> find_cases() {
  std::vector<GoldenCase> cases;
  const std::regex expected_re(R"(expected-step(\d+)\.(.+))");
  const std::vector<fs::path> folders = model_folders(golden_dir());

  for (const fs::path& folder : folders) {
    std::vector<GoldenCase> found;
    bool has_inputs = false;
    std::vector<std::pair<int, std::string>> written;  // (step, file name)
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      std::smatch m;
      if (std::regex_match(name, m, expected_re)) {
        const int steps = std::stoi(m[1].str());
        const std::string rest = m[2].str();
        if (rest == "txt") {
          GoldenCase c;
          c.folder = folder.filename().string();
          c.steps = steps;
          found.push_back(c);
        } else if (rest.size() > 11 && rest.compare(rest.size() - 11, 11, ".turtle.txt") == 0) {
          // lpfg's interpreted-string dump: informative, not compared.
        } else {
          written.emplace_back(steps, rest);
        }
      } else if (name != "lsystem.l" && name != "README.md") {
        has_inputs = true;
      }
    }
    for (GoldenCase& c : found) {
      c.needs_working_dir = has_inputs || !written.empty();
      for (const auto& [steps, file] : written)
        if (steps == c.steps) c.written.push_back(file);
    }
    std::sort(found.begin(), found.end(), [](const GoldenCase& a, const GoldenCase& b) { return a.steps < b.steps; });
    cases.insert(cases.end(), found.begin(), found.end());
  }
  return cases;
}

std::string case_name(const testing::TestParamInfo<GoldenCase>& info) {
  std::string name = info.param.folder + "_step" + std::to_string(info.param.steps);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

std::string without_final_newline(std::string s) {
  if (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

std::vector<std::string> split_modules(const std::string& s) {
  std::vector<std::string> modules;
  std::istringstream in(s);
  std::string m;
  while (in >> m) modules.push_back(m);
  return modules;
}

bool starts_number(const char* at) {
  if (*at == '-' || *at == '+') ++at;
  if (*at == '.') ++at;
  return std::isdigit(static_cast<unsigned char>(*at)) != 0;
}

// The same string, a number in the reference text (%.9g of a float, %.17g
// of a double) matching one in Sylva's (shortest exact text) when both read
// back to the same double, or, for a reference number of at most 9
// significant digits (a float's), to the same float.
bool same_text(const std::string& expected, const std::string& actual) {
  const char *e = expected.c_str(), *a = actual.c_str();
  const char *e_end = e + expected.size(), *a_end = a + actual.size();
  while (e < e_end && a < a_end) {
    const bool in_name = e > expected.c_str() && (std::isalnum(static_cast<unsigned char>(e[-1])) || e[-1] == '_');
    if (!in_name && starts_number(e) && starts_number(a)) {
      char *e_stop = nullptr, *a_stop = nullptr;
      const double ed = std::strtod(e, &e_stop), ad = std::strtod(a, &a_stop);
      int digits = 0;  // significant: from the first nonzero one
      for (const char* c = e; c < e_stop && *c != 'e' && *c != 'E'; ++c)
        if (std::isdigit(static_cast<unsigned char>(*c)) && (digits > 0 || *c != '0')) ++digits;
      const bool same = ed == ad || (digits <= 9 && std::strtof(e, nullptr) == std::strtof(a, nullptr));
      if (!same) return false;
      e = e_stop;
      a = a_stop;
      continue;
    }
    if (*e++ != *a++) return false;
  }
  return e == e_end && a == a_end;
}

// Where two strings first differ, module by module, for the failure message
// (the strings themselves can be hundreds of kilobytes).
std::string describe_difference(const std::string& expected, const std::string& actual) {
  const std::vector<std::string> e = split_modules(expected), a = split_modules(actual);
  std::ostringstream out;
  out << "expected " << e.size() << " modules (" << expected.size() << " bytes), got " << a.size() << " modules ("
      << actual.size() << " bytes)\n";
  std::size_t i = 0;
  while (i < e.size() && i < a.size() && same_text(e[i], a[i])) ++i;
  if (i == e.size() && i == a.size()) {
    out << "same modules, different separators";
    return out.str();
  }
  out << "first difference at module " << i << ":\n  expected: " << (i < e.size() ? e[i] : "(end)")
      << "\n  actual:   " << (i < a.size() ? a[i] : "(end)") << "\n  context (expected):";
  for (std::size_t k = i >= 3 ? i - 3 : 0; k < std::min(e.size(), i + 4); ++k) out << ' ' << e[k];
  out << "\n  context (actual):  ";
  for (std::size_t k = i >= 3 ? i - 3 : 0; k < std::min(a.size(), i + 4); ++k) out << ' ' << a[k];
  if (expected.size() + actual.size() < 4000) out << "\n  expected string: " << expected << "\n  actual string:   " << actual;
  return out.str();
}

// A fresh copy of the folder (model and inputs, no expected files) to run in.
std::string working_copy(const GoldenCase& c) {
  const std::string dir = make_temp_dir("golden-" + c.folder + "-step" + std::to_string(c.steps));
  for (const auto& entry : fs::directory_iterator(fs::path(golden_dir()) / c.folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("expected-", 0) == 0 || name == "README.md") continue;
    fs::copy(entry.path(), fs::path(dir) / name);
  }
  return dir;
}

class Golden : public testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesLpfg) {
  const GoldenCase& c = GetParam();
  const fs::path folder = fs::path(golden_dir()) / c.folder;
  const std::string expected =
      without_final_newline(read_text((folder / ("expected-step" + std::to_string(c.steps) + ".txt")).string()));
  ASSERT_FALSE(expected.empty()) << "no expected string in " << folder;

  std::string actual;
  if (!c.needs_working_dir) {
    actual = derive_string((folder / "lsystem.l").string(), c.steps);
  } else {
    const std::string dir = working_copy(c);
    const ProcessResult r = run_sylva({"run", "lsystem.l", "--steps", std::to_string(c.steps)}, dir);
    ASSERT_EQ(r.exit_code, 0) << "sylva failed in " << dir << ":\n" << r.err;
    actual = without_final_newline(r.out);
    for (const std::string& file : c.written) {
      const fs::path written = fs::path(dir) / file;
      ASSERT_TRUE(fs::exists(written)) << "the model did not write " << file;
      EXPECT_EQ(read_text(written.string()),
                read_text((folder / ("expected-step" + std::to_string(c.steps) + "." + file)).string()))
          << "the " << file << " the model wrote after " << c.steps << " steps";
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  EXPECT_TRUE(same_text(expected, actual)) << c.folder << " after " << c.steps << " steps:\n"
                                  << describe_difference(expected, actual);
}

// Names read golden/Golden.MatchesLpfg/thesis_L26_branching_step33: both "golden" (ctest -R golden)
// and "Golden" (--gtest_filter='*Golden*') select them, as they do the tests below.
INSTANTIATE_TEST_SUITE_P(golden, Golden, testing::ValuesIn(find_cases()), case_name);

// The folders must be there: an empty scan would pass vacuously.
TEST(GoldenSet, golden_cases_present) {
  const std::vector<GoldenCase> cases = find_cases();
  EXPECT_GE(cases.size(), 150u);
  const bool has_l30_output = std::any_of(cases.begin(), cases.end(), [](const GoldenCase& c) {
    return c.folder == "thesis-L30-control-statements" && c.steps == 100 && c.written.size() == 1;
  });
  EXPECT_TRUE(has_l30_output) << "thesis-L30-control-statements' expected-step100.output.dat not found";
}

// lpfg says "Maximum decomposition depth reached for module A" when the limit
// stops a recursive decomposition (thesis App. A.6.11 with maximum depth 4);
// with maximum depth 6 the recursion of A(5) ends by itself.
std::size_t count_depth_warnings(const std::string& folder, int steps) {
  const ProcessResult r = run_sylva(
      {"run", (fs::path(golden_dir()) / folder / "lsystem.l").string(), "--steps", std::to_string(steps)});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::size_t count = 0;
  for (std::size_t pos = r.err.find("maximum decomposition depth"); pos != std::string::npos;
       pos = r.err.find("maximum decomposition depth", pos + 1))
    ++count;
  return count;
}

TEST(GoldenDecompositionDepth, golden_depth_4_warns) {
  EXPECT_EQ(count_depth_warnings("thesis-A611-decomposition-depth-4", 0), 1u);
}

TEST(GoldenDecompositionDepth, golden_depth_6_silent) {
  EXPECT_EQ(count_depth_warnings("thesis-A611-decomposition-depth", 0), 0u);
}

}  // namespace
}  // namespace sylva::test
