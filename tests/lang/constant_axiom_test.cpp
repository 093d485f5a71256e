// Long axioms whose parameters are literals become data in the compiled
// model: they compile in seconds, and the string they give is the one their
// text describes, with modules whose parameters are expressions in their
// places among them.
#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::test {
namespace {

struct LongAxiom {
  std::string model;
  std::string string;  // what the axiom derives to in no steps
};

// `n` modules, ten to a line; every 1000th has an expression for a parameter.
LongAxiom long_axiom(int n) {
  LongAxiom a;
  a.model = "module A(float);\nmodule B(float, int);\nmodule C;\nderivation length: 0;\naxiom:";
  for (int k = 0; k < n; ++k) {
    const std::string half = std::to_string(k) + ".5";
    std::string written, shown;
    switch (k % 3) {
      case 0:
        written = k % 1000 == 0 ? "A(" + std::to_string(k) + " + 0.5f)" : "A(" + half + ")";
        shown = "A(" + half + ")";
        break;
      case 1:
        written = "B(-" + half + ", " + std::to_string(k) + ")";
        shown = "B(-" + half + "," + std::to_string(k) + ")";
        break;
      default: written = shown = "C";
    }
    a.model += (k % 10 == 0 ? "\n  " : " ") + written;
    a.string += (k ? " " : "") + shown;
  }
  a.model += ";\n";
  return a;
}

std::string write_model(const std::string& name, const std::string& text) {
  const std::string path = make_temp_dir(name) + "/model.l";
  std::ofstream(path) << text;
  return path;
}

TEST(ConstantAxiom, TwentyThousandModules) {
  const LongAxiom a = long_axiom(20000);
  EXPECT_EQ(derive_string(write_model("axiom-20k", a.model), 0), a.string);
}

TEST(ConstantAxiom, AHundredThousandModules) {
  const LongAxiom a = long_axiom(100000);
  EXPECT_EQ(derive_string(write_model("axiom-100k", a.model), 0), a.string);
}

// Literals of every form and type the translator encodes, against the same
// values passed through a function (which the compiler converts).
TEST(ConstantAxiom, EncodedLiteralsEqualCompiledOnes) {
  const char* const declarations =
      "template <class T> T same(T v) { return v; }\n"
      "module P(float, double, int, unsigned, char, bool, short, long, unsigned char);\n"
      "derivation length: 0;\n";
  const std::vector<std::vector<std::string>> rows = {
      {"0.1", "0.1", "2.7", "-1", "65", "0.5", "-70000", "-2147483648", "300"},
      {"16777217", "0.1f", "-2.7", "4294967297", "-1", "0", "40000", "9223372036854775807", "-1"},
      {"1e-3", "1e300", "(-(3))", "+7", "'A'", "2", "1.9", "-0.0", "255.9"},
      {"-0.0", ".5", "0", "3000000000", "200", "-0.0", "-32769", "123456789012", "0"},
  };
  std::string literal = declarations, called = declarations;
  literal += "axiom:";
  called += "axiom:";
  for (const auto& row : rows) {
    literal += " P(";
    called += " P(";
    for (std::size_t k = 0; k < row.size(); ++k) {
      literal += (k ? ", " : "") + row[k];
      called += (k ? ", same(" : "same(") + row[k] + ")";
    }
    literal += ")";
    called += ")";
  }
  literal += ";\n";
  called += ";\n";
  const std::string from_literals = derive_string(write_model("axiom-literals", literal), 0);
  EXPECT_EQ(from_literals, derive_string(write_model("axiom-called", called), 0));
  // 0.1f and 0.1 in their shortest exact text.
  EXPECT_NE(from_literals.find("P(0.1,0.1,2,4294967295,65,1,-4464,-2147483648,44)"),
            std::string::npos)
      << from_literals;
}

}  // namespace
}  // namespace sylva::test
