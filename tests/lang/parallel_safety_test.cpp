// The analysis of which rule bodies may run in parallel, from L+C and cpfg
// text: bodies that only compute and produce are safe; those that assign
// what is not theirs, print, draw random numbers, stop the run, change the
// group, read new context or call functions that do are not, with the reason.
#include <gtest/gtest.h>

#include <string>

#include "lang/model_ir_text.h"
#include "lang/parallel_safety.h"

namespace sylva::test {
namespace {

// The verdict on the model's only rule: "" when safe, else the reason.
lang::RuleSafety only_rule(const lang::Model& model) {
  const std::vector<lang::RuleSafety> verdicts = lang::rule_safety(model);
  EXPECT_EQ(verdicts.size(), 1u);
  return verdicts.empty() ? lang::RuleSafety{"no rule"} : verdicts[0];
}

std::string reason(const std::string& globals_and_functions, const std::string& body) {
  return only_rule(parse_lc_text("module A(float);\n" + globals_and_functions + "\nA(x) :\n{\n" + body + "\n}\n"))
      .reason;
}

TEST(ParallelSafety, ComputingAndProducingIsSafe) {
  EXPECT_EQ(reason("", "produce A(x + 1);"), "");
  EXPECT_EQ(reason("", "float y = sqrt(x) * sin(x); V3f v(1, 2, y); v.Normalize(); produce A(pow(y, 2) + v.x);"), "");
  EXPECT_EQ(reason("", "for (int i = 0; i < 3; ++i) x += i; if (x > (2 + 1)) produce A(std::max(x, 2.0f));"), "");
  EXPECT_EQ(reason("", "float a[3] = {1, 2, 3}; a[1] = x; int n = StepNo(); n++; produce A(a[1] + n);"), "");
}

TEST(ParallelSafety, ReadingGlobalsAndCallingPureModelFunctionsIsSafe) {
  const std::string globals = "const float kRate = 2;\nfloat scale = 1;\n"
                              "float grow(float v, const V3f& d) { float r = v * kRate; return r + d.x; }\n";
  EXPECT_EQ(reason(globals, "produce A(grow(x, V3f(0, 0, 1)) * scale);"), "");
}

TEST(ParallelSafety, FunctionsMayWriteWhatTheCallerOwns) {
  const std::string update = "struct Cell { float a; };\nbool Update(Cell& c, float d, Cell& out) { c.a = d; out = c; return true; }\n";
  EXPECT_EQ(reason(update, "Cell c, d; Cell e; if (Update(e, x, d)) produce A(e.a); produce A(x);"), "");
  EXPECT_EQ(reason(update + "Cell g;", "Cell e; Update(e, x, g); produce A(x);"),
            "passes `Update` something not its own to write (line 7)");
}

TEST(ParallelSafety, AssigningAGlobalIsUnsafe) {
  EXPECT_EQ(reason("int count = 0;", "count = count + 1; produce A(x);"), "assigns `count`, which is not its own (line 5)");
  EXPECT_EQ(reason("int count = 0;", "++count; produce A(x);"), "changes `count`, which is not its own (line 5)");
  EXPECT_EQ(reason("V3f g;", "g.x = x; produce A(x);"), "assigns `g`, which is not its own (line 5)");
  EXPECT_EQ(reason("V3f g;", "g.Set(1, 2, 3); produce A(x);"), "calls `Set` on something not its own (line 5)");
  // A local of an inner block does not hide the global after it.
  EXPECT_EQ(reason("float t;", "{ float t = 1; t = 2; } t = 3; produce A(x);"),
            "assigns `t`, which is not its own (line 5)");
  // Nor does a reference make a global the body's own.
  EXPECT_EQ(reason("float t;", "float& r = t; r = 2; produce A(x);"), "assigns `r`, which is not its own (line 5)");
  EXPECT_EQ(reason("float t;", "float* p = &t; produce A(x);"),
            "takes the address of something not its own (line 5)");
}

TEST(ParallelSafety, SideEffectsAndUnknownCallsAreUnsafe) {
  EXPECT_EQ(reason("", "Printf(\"%f\", x); produce A(x);"), "calls `Printf`, which is not known to be pure (line 5)");
  EXPECT_EQ(reason("", "if (x > 3) Stop(); produce A(x);"), "calls `Stop`, which is not known to be pure (line 5)");
  EXPECT_EQ(reason("", "UseGroup(1); produce A(x);"), "calls `UseGroup`, which is not known to be pure (line 5)");
  EXPECT_EQ(reason("", "static int n = 0; produce A(n);"), "declares a static variable (line 5)");
  EXPECT_EQ(reason("", "produce A(func(1, x));"), "calls `func`, which is not known to be pure (line 5)");
  EXPECT_EQ(reason("int n;\nvoid bump() { n++; }", "bump(); produce A(x);"),
            "calls `bump`, which changes `n`, which is not its own (line 3) (line 6)");
  EXPECT_EQ(reason("float g;\nvoid take(float& v) { v = 1; }", "take(g); produce A(x);"),
            "passes `take` something not its own to write (line 6)");
}

TEST(ParallelSafety, RanIsSafeOnlyWhereItIsKeyed) {
  const lang::RuleSafety direct = only_rule(parse_lc_text("module A(float);\nA(x) : { produce A(ran(x)); }\n"));
  EXPECT_EQ(direct.reason, "");
  EXPECT_TRUE(direct.draws_random);
  const lang::RuleSafety through = only_rule(
      parse_lc_text("module A(float);\nfloat jitter(float v) { return v + ran(1); }\nA(x) : { produce A(jitter(x)); }\n"));
  EXPECT_EQ(through.reason, "");
  EXPECT_TRUE(through.draws_random);
  EXPECT_FALSE(only_rule(parse_lc_text("module A(float);\nA(x) : { produce A(x); }\n")).draws_random);
}

TEST(ParallelSafety, NewContextIsUnsafeOldContextIsSafe) {
  EXPECT_EQ(reason("", "float y; if (InRightContext(A(y))) produce A(y); produce A(x);"), "");
  EXPECT_EQ(reason("", "float y; if (InNewLeftContext(A(y))) produce A(y); produce A(x);"),
            "reads the new string as context (line 5)");
  EXPECT_EQ(reason("float g;", "if (InLeftContext(A(g))) produce A(g); produce A(x);"),
            "copies context into something not its own (line 5)");
}

TEST(ParallelSafety, CpfgStatementsAssignGlobals) {
  const lang::Model plain = parse_cpfg_text("Lsystem: 1\nderivation length: 2\naxiom: A(1)\nA(x) --> A(x+1)\nendlsystem\n");
  EXPECT_EQ(only_rule(plain).reason, "");
  const lang::Model counting =
      parse_cpfg_text("Lsystem: 1\nderivation length: 2\naxiom: A(1)\nA(x) : {n=n+1;} --> A(n)\nendlsystem\n");
  EXPECT_EQ(only_rule(counting).reason, "assigns `v_n`, which is not its own (line 4)");
  // cpfg's ran() draws from the model's one stream.
  const lang::Model drawing = parse_cpfg_text("Lsystem: 1\nderivation length: 2\naxiom: A(1)\nA(x) --> A(ran(x))\nendlsystem\n");
  EXPECT_EQ(only_rule(drawing).reason.rfind("calls `::sylva::rt::cpfg::ran`", 0), 0u) << only_rule(drawing).reason;
}

}  // namespace
}  // namespace sylva::test
