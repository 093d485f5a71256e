// The cpfg language as cpfg itself reads it (its preprocessor vlabcpp, its
// lexer lsys_input.l and parser lsys_input.y, generate.c, utility.c), where
// that goes past or against the CPFG manual. Each expected string is the one
// the reference cpfg printed for the same model (cpfg -g -m colors.map -str
// out.str model.l view.v, with a view file of "angle factor: 4").
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_support.h"

namespace sylva::test {
namespace {

struct CpfgRun {
  int exit_code;
  std::string string;  // the final string, without the newline
  std::string err;
};

CpfgRun run_cpfg(const std::string& name, const std::string& model, const std::string& view = "angle factor: 4\n") {
  const std::string dir = make_temp_dir("cpfg-dialect-" + name);
  std::ofstream(dir + "/m.l") << model;
  std::ofstream(dir + "/v.v") << view;
  const ProcessResult r = run_sylva({"run", "m.l", "v.v"}, dir);
  std::string out = r.out;
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return CpfgRun{r.exit_code, out, r.err};
}

// ---- the preprocessor ------------------------------------------------------------

TEST(CpfgDialect, HashLineThatStartsNoDirectiveIsText) {
  // vlabcpp passes "\t#(0.5) F(2)" through (# is also a turtle symbol); a
  // line of its own is left empty where a directive stood.
  const CpfgRun r = run_cpfg("hash",
                         "#define W 0.5\nLsystem: 1\nderivation length: 2\nAxiom: A\nA --> F(1)\n"
                         "\t#(W) F(2)\n\t\n\tB\nB --> C\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "F(1)#(0.5)F(2)C");
}

TEST(CpfgDialect, StrayBackslashOfAContinuedMacroIsReadPast) {
  // "#define W(x) \\" + newline leaves a "\" in the macro's text; cpfg's
  // lexer passes it by in an expression.
  const CpfgRun r = run_cpfg("backslash",
                         "#define W(x) \\\\\n (2 * x)\nLsystem: 1\nderivation length: 1\nAxiom: A\n"
                         "A --> B(1 + W(3))\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(7)");
  EXPECT_NE(r.err.find("m.l:6:13: warning: '\\' read past"), std::string::npos) << r.err;
}

// ---- statements and lines -----------------------------------------------------------

TEST(CpfgDialect, TabContinuesAStatementSpacesStartANewOne) {
  // "  B --> D" starts a production of its own (a second one for B, never
  // used); "\tB" after a line of only a tab still continues A's successor.
  const CpfgRun r = run_cpfg("lines",
                         "Lsystem: 1\nderivation length: 2\nAxiom: A\nA --> F(1)\n\t\n\tB\nB --> C\n  B --> D\n"
                         "endlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "F(1)C");
}

TEST(CpfgDialect, BlocksSpanLinesExpressionStatementsAndUnknownNames) {
  // Braces of an expression part (Start:, a pre-condition) read across
  // lines whatever they start with; "y - z;" is a statement whose value is
  // dropped; w was never given a value: cpfg warns and reads 0.
  const CpfgRun r = run_cpfg("blocks",
                         "Lsystem: 1\nStart: {\n  n = 0;\n}\nderivation length: 2\nAxiom: A(1)\nA(x) : {\n"
                         "   y = x * 2;\n   if (y > 1) { z = 3; }\n   else { z = 4; }\n   y - z;\n"
                         "  } x > 0 --> A(y)B(z,w)\n* < B(a,b) > * --> B(a+1,b)\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "A(4)B(3,0)B(4,0)");
  EXPECT_NE(r.err.find("m.l:12:23: warning: unknown variable 'w' read as 0"), std::string::npos) << r.err;
}

// cpfg keeps one table of variables: the second module's loop does not run,
// and x keeps the first module's 3 (the reference cpfg gives B(3)B(3)).
TEST(CpfgDialect, VariablesKeepTheirValuesFromModuleToModule) {
  const CpfgRun r = run_cpfg("kept", "Lsystem: 1\nderivation length: 1\nAxiom: A(3)A(0)\n"
                                     "A(n) : * {i=0; while (i<n) {x=n; i=i+1;}} --> B(x)\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(3)B(3)");
}

TEST(CpfgDialect, UnknownNameInASuccessorReadsZero) {
  const CpfgRun r = run_cpfg("unknown", "Lsystem: 1\nderivation length: 2\nAxiom: A(1)\nA(x) --> A(y+1)\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "A(1)");
  EXPECT_NE(r.err.find("m.l:4:12: warning: unknown variable 'y'"), std::string::npos) << r.err;
}

// ---- contexts -----------------------------------------------------------------------

TEST(CpfgDialect, RightContextGoesThroughIgnoredBrackets) {
  // consider: without [ and ]: cpfg reads the right context past them, into
  // and out of branches. With them considered, branches stand.
  CpfgRun r = run_cpfg("flat", "Lsystem: 1\nderivation length: 1\nconsider: AB\nAxiom: [A]B[CA]B\nA > B --> X\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "[X]B[CX]B");
  r = run_cpfg("branches", "Lsystem: 1\nderivation length: 1\nconsider: AB[]\nAxiom: [A]B[CA]B\nA > B --> X\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "[A]B[CA]B");
  r = run_cpfg("ignore-open", "Lsystem: 1\nderivation length: 1\nignore: [\nAxiom: A[B]C\nA > B --> X\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "X[B]C");
}

TEST(CpfgDialect, ProductionsReachTheCharactersOfTurtleCommands) {
  // cpfg's string holds a module a character: o(r) rewrites the o of
  // @o(0.2); the P of ?P(x,y,z) has a context of its own; a predecessor's
  // @o is @ then o. The turtle still reads @o and ?P.
  const CpfgRun r = run_cpfg("characters",
                             "Lsystem: 1\nderivation length: 2\nignore: F\nAxiom: AF@o(0.2)?P(0,0,0)G(1)\n"
                             "o(r) --> o(r+1)\nA > @o(r) --> B(r)\nP(x,y,z) > G(t) --> P(x+10,y,z)G(t)\n"
                             "G(t) --> G(t+1)\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(0.2)F@o(2.2)?P(0,1,0)G(1)G(2)G(3)");
}

// ---- stochastic productions -----------------------------------------------------------

TEST(CpfgDialect, ProbabilitiesAreExpressionsSharedAmongTheProductionsThatApply) {
  // The total is that of the productions whose context and condition hold;
  // a probability may use the parameters (n, 0 for A(0)).
  const CpfgRun r = run_cpfg("stochastic",
                         "Lsystem: 1\nseed: 5\nderivation length: 4\nAxiom: A(0)A(0)A(0)A(0)A(0)A(0)\n"
                         "A(n) : n < 2 --> A(n+1)B : 1\nA(n) : n >= 2 --> A(n+1)C : 1\nA(n) --> A(n+1)D : n\n"
                         "B --> X : 3\nB --> Y : 1\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "A(4)CCXXA(4)DDDXA(4)DDXYA(4)DDDXA(4)DDDXA(4)DDDX");
}

TEST(CpfgDialect, EveryModuleDrawsACutToo) {
  // cpfg in batch starts drand48 from its zero state whatever the seed; the
  // cut draws like any module, the modules it removes do not.
  for (const char* seed : {"1", "77"}) {
    const CpfgRun r = run_cpfg(std::string("cut-") + seed,
                           std::string("Lsystem: 1\nseed: ") + seed +
                               "\nderivation length: 1\nAxiom: [%X]AAAAAAAA\nA --> B : 1\nA --> C : 1\nendlsystem\n");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.string, "[]BBBBBCBB") << seed;
  }
}

TEST(CpfgDialect, ProbabilitiesOutsideStochasticProductionsAreReadPast) {
  // No seed:, or a decomposition or homomorphism production: the first
  // production that matches applies; cpfg warns for the first kind only.
  const CpfgRun r = run_cpfg("ignored-probability",
                         "Lsystem: 1\nderivation length: 1\nAxiom: AD\nA --> B : 0\nA --> C : 1\n"
                         "decomposition\nD --> E : 0\nD --> G : 1\nhomomorphism\nB --> F : 0\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "BE");
  EXPECT_NE(r.err.find("m.l:4:11: warning: probability ignored"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("m.l:7:11: warning: probability ignored"), std::string::npos) << r.err;
}

// ---- random functions --------------------------------------------------------------------

TEST(CpfgDialect, RandomFunctionsDrawAsCpfgDoes) {
  // Their own erand48 stream from {0x330E, 0, 0}; parameters left to right;
  // the first nran before any srand gives its mean.
  CpfgRun r = run_cpfg("random", "Lsystem: 1\nderivation length: 1\nAxiom: AAA\nA --> B(ran(1),nran(5,1),nran(5,1))\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(0.170828,5,4.61274)B(0.870465,5.23977,6.39756)B(0.692194,5.37801,5.90999)");
  r = run_cpfg("srand",
               "Lsystem: 1\nStart: {srand(3);}\nderivation length: 1\nAxiom: AAA\n"
               "A --> B(ran(1),nran(5,1),bran(2,3),biran(10,0.3))\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string,
            "B(0.783235,4.58917,0.256068,5)B(0.9071,5.7935,0.103117,2)B(0.627672,4.45959,0.636634,5)");
}

TEST(CpfgDialect, HomomorphismSeedGivesItsProductionsAStreamOfTheirOwn) {
  // With its own seed:, the homomorphism's ran() (run after every step,
  // for ?P) leaves the productions' ran() alone, and restarts each time.
  const std::string model =
      "Lsystem: 1\nderivation length: 3\nAxiom: B(ran(1))A?P(0,0,0)\nA --> A\nB(x) --> B(ran(1))\n"
      "homomorphism\n";
  CpfgRun r = run_cpfg("homomorphism-seed", model + "seed: 7\nA --> +(ran(90))F\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(0.870465)A?P(-0.406417,0.913688,0)");
  r = run_cpfg("homomorphism-no-seed", model + "A --> +(ran(90))F\nendlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.string, "B(0.692194)A?P(-0.547402,0.83687,0)");
}

// ---- the turtle's frame -------------------------------------------------------------------

// The sign of a zero is not compared.
std::string without_negative_zeros(std::string s) {
  for (std::size_t at = s.find("-0"); at != std::string::npos; at = s.find("-0", at + 1))
    if (at + 2 >= s.size() || s[at + 2] == ',' || s[at + 2] == ')') s.erase(at, 1);
  return s;
}

TEST(CpfgDialect, TurtleFrameIsCpfgs) {
  // H = +y, L = -x, U = -z at first: / rolls L towards that U.
  const CpfgRun r = run_cpfg("frame",
                         "Lsystem: 1\nderivation length: 1\nAxiom: /(90)+(30)?H(0,0,0)?L(0,0,0)?U(0,0,0)\nZ --> Z\n"
                         "endlsystem\n");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(without_negative_zeros(r.string),
            "/(90)+(30)?H(-3.06162e-17,0.866025,-0.5)?L(-5.30288e-17,-0.5,-0.866025)?U(1,0,-6.12323e-17)");
}

}  // namespace
}  // namespace sylva::test
