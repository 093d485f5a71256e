// InLeftContext, InRightContext, InNewLeftContext and InNewRightContext in
// rule bodies (LPFG manual 3.3): tiny L+C models run through the engine.
// Every expected string is worked out by hand from the manual's rules (the
// comment above each expectation gives the trace).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "api/simulation.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// A model file with modules A..E (one int each), K, M, H, R, U (one int each)
// and I (none) declared, then `body`.
std::string write_model(const std::string& test, const std::string& body) {
  return write_temp_file("in-body-" + test, "model.l",
                         "#include <lpfgall.h>\n"
                         "module A(int); module B(int); module C(int); module D(int); module E(int);\n"
                         "module K(int); module M(int); module H(int); module R(int); module U(int);\n"
                         "module I();\n" +
                             body);
}

// The manual's first example (F, G renamed K, M: F and G are predefined): the body's tests do what `K(x) < M(l) > H(y)` does.
TEST(InBodyContext, LeftAndRightTestsBindParameters) {
  // M(3): left K(2), right H(4) -> M(2*10 + 4). M(5) has no K on its left -> M(-5).
  const std::string model = write_model("left-right",
                                        "derivation length: 1;\nAxiom: K(2) M(3) H(4) M(5) H(6);\n"
                                        "M(l): { int x, y;\n"
                                        "  if (InLeftContext(K(x)) && InRightContext(H(y))) produce M(x * 10 + y);\n"
                                        "  produce M(-l); }\n");
  EXPECT_EQ(derive_string(model), "K(2) M(24) H(4) M(-5) H(6)");
}

// 3.3: with a context-sensitive predecessor, InLeftContext begins before the
// predecessor's left context. The manual's E(1) K(2) M(3) H(4) example.
TEST(InBodyContext, TestBeginsBeyondPredecessorContext) {
  // M(3) matches K(2) < M > H(4); InLeftContext(K(x)) then looks at E(1): false -> M(3+1).
  // InRightContext(H(h)) after the right context H(4) looks at R(9): false as well.
  const std::string model = write_model("beyond",
                                        "derivation length: 1;\nAxiom: E(1) K(2) M(3) H(4) R(9);\n"
                                        "K(x) < M(length) > H(y): { int x2, h;\n"
                                        "  if (InRightContext(H(h))) produce M(100);\n"
                                        "  if InLeftContext(K(x2)) produce M(x2);\n"
                                        "  else produce M(length + 1); }\n");
  EXPECT_EQ(derive_string(model), "E(1) K(2) M(4) H(4) R(9)");
}

// 3.3: tests read the string like a stream. A test that succeeds moves on past
// what it matched; one that fails moves nothing.
TEST(InBodyContext, TestsReadContextAsAStream) {
  // M(0): left K(2) then K(1); right R(7) then U(8); H(h) fails on both sides
  // without moving. -> M(2*1000 + 1*100 + 7*10 + 8) = M(2178).
  const std::string model = write_model("stream",
                                        "derivation length: 1;\nAxiom: K(1) K(2) M(0) R(7) U(8);\n"
                                        "M(z): { int a, b, c, d, h;\n"
                                        "  if (InLeftContext(H(h)) || InRightContext(H(h))) produce M(-1);\n"
                                        "  if (InLeftContext(K(a)) && InLeftContext(K(b)) && InRightContext(R(c)) &&\n"
                                        "      InRightContext(U(d)))\n"
                                        "    produce M(a * 1000 + b * 100 + c * 10 + d);\n"
                                        "  produce M(-2); }\n");
  EXPECT_EQ(derive_string(model), "K(1) K(2) M(2178) R(7) U(8)");
}

// A pattern of several modules, in string order, as in a predecessor.
TEST(InBodyContext, MultiModulePatterns) {
  // M(0): left "K(1) H(2)" -> a=1, b=2; right "R(3) U(4)" -> c=3, d=4 -> M(1234).
  const std::string model = write_model("multi",
                                        "derivation length: 1;\nAxiom: K(1) H(2) M(0) R(3) U(4);\n"
                                        "M(z): { int a, b, c, d;\n"
                                        "  if (InLeftContext(K(a) H(b)) && InRightContext(R(c) U(d)))\n"
                                        "    produce M(a * 1000 + b * 100 + c * 10 + d);\n"
                                        "  produce M(-1); }\n");
  EXPECT_EQ(derive_string(model), "K(1) H(2) M(1234) R(3) U(4)");
}

// Chapter 9 applies: left context is the path to the root (sibling branches
// skipped), right context skips lateral branches; ignore: passes over modules.
TEST(InBodyContext, BranchesAndIgnoreAsInPredecessors) {
  // A(1) [B(2)] I C(3): C's left passes I (ignored), skips [B(2)], finds A(1) -> C(31).
  // A(1)'s right skips the branch [B(2)] and I, finds C(3) -> A(13).
  // B(2) is in a branch: its right is the branch end -> no C -> B(-2); its left is A(1) -> ...
  // but the B rule only asks for the right.
  const std::string model = write_model("branches",
                                        "ignore: I;\nderivation length: 1;\nAxiom: A(1) [B(2)] I C(3);\n"
                                        "C(z): { int a; if (InLeftContext(A(a))) produce C(z * 10 + a); produce C(-z); }\n"
                                        "A(z): { int c; if (InRightContext(C(c))) produce A(z * 10 + c); produce A(-z); }\n"
                                        "B(z): { int c; if (InRightContext(C(c))) produce B(c); produce B(-z); }\n");
  EXPECT_EQ(derive_string(model), "A(13) SB B(-2) EB I C(31)");
}

// Brackets in the pattern, as in a predecessor: InRightContext([B(b)] C(c)).
TEST(InBodyContext, BracketsInPatterns) {
  // A(1) [B(2)] C(3): the right context of A starts with the branch [B(2)], then C(3) -> A(123).
  const std::string model = write_model("brackets",
                                        "derivation length: 1;\nAxiom: A(1) [B(2)] C(3);\n"
                                        "A(z): { int b, c; if (InRightContext([B(b)] C(c))) produce A(z * 100 + b * 10 + c);\n"
                                        "  produce A(-z); }\n");
  EXPECT_EQ(derive_string(model), "A(123) SB B(2) EB C(3)");
}

// 3.1.4: in a ring L-system the tests go across the ends of the string.
TEST(InBodyContext, RingTestsWrapAround) {
  // A(1) B(2) C(3) as a ring: A's left neighbour is C(3), C's right neighbour A(1).
  const std::string model = write_model("ring",
                                        "ring L-system: 1;\nderivation length: 1;\nAxiom: A(1) B(2) C(3);\n"
                                        "A(z): { int c; if (InLeftContext(C(c))) produce A(c); produce A(-1); }\n"
                                        "C(z): { int a; if (InRightContext(A(a))) produce C(a); produce C(-1); }\n");
  EXPECT_EQ(derive_string(model), "A(3) B(2) C(1)");
}

// 3.1.3 / 3.3: InNewLeftContext reads the new string going forward, like <<.
TEST(InBodyContext, NewLeftContextReadsNewString) {
  // A(1) -> A(2). B#1: new left is A(2) -> B(2); old left (InLeftContext) would be A(1).
  // B#2: new left is B(2), not A -> B(-1).
  const std::string model = write_model("new-left",
                                        "derivation length: 1;\nAxiom: A(1) B(0) B(0);\n"
                                        "A(x): { produce A(x + 1); }\n"
                                        "B(y): { int x; if (InNewLeftContext(A(x))) produce B(x); produce B(-1); }\n");
  EXPECT_EQ(derive_string(model), "A(2) B(2) B(-1)");
}

// What a body has nproduce'd for its own successor is not new context.
TEST(InBodyContext, NewLeftContextExcludesOwnSuccessor) {
  // B(0): nproduce A(9); the new string before B's successor ends with C(5) -> B(5).
  const std::string model = write_model("new-left-own",
                                        "derivation length: 1;\nAxiom: C(5) B(0);\n"
                                        "B(y): { int x, c; nproduce A(9);\n"
                                        "  if (InNewLeftContext(A(x))) produce B(x);\n"
                                        "  if (InNewLeftContext(C(c))) produce B(c);\n"
                                        "  produce B(-1); }\n");
  EXPECT_EQ(derive_string(model), "C(5) A(9) B(5)");
}

// Backward derivation: InNewRightContext reads the new string built from the
// right; InNewLeftContext has no new string to read and is false. Forward,
// InNewRightContext is false.
TEST(InBodyContext, NewRightContextOnlyBackward) {
  const std::string rules =
      "derivation length: 1;\nAxiom: B(0) A(1);\n"
      "A(x): { produce A(x + 1); }\n"
      "B(y): { int x; if (InNewRightContext(A(x))) produce B(x); if (InNewLeftContext(A(x))) produce B(50);\n"
      "  produce B(-1); }\n";
  // Backward: A(1) -> A(2) first; B's new right is A(2) -> B(2).
  EXPECT_EQ(derive_string(write_model("new-right-backward", "Start: { Backward(); }\n" + rules)), "B(2) A(2)");
  // Forward: new right does not exist, new left is empty -> B(-1).
  EXPECT_EQ(derive_string(write_model("new-right-forward", rules)), "B(-1) A(2)");
}

// Decomposition rules test context in the string being decomposed, and new
// left context in the decomposition built so far.
TEST(InBodyContext, DecompositionRules) {
  // Decomposition of the axiom: A(1) -> E(1) D(7).
  // B(0): old left is A(1) -> x=1; new left is D(7) -> d=7 -> C(17).
  const std::string model = write_model("decomposition",
                                        "derivation length: 0;\nAxiom: A(1) B(0);\n"
                                        "decomposition:\n"
                                        "A(x): { produce E(x) D(7); }\n"
                                        "B(y): { int x, d; if (InLeftContext(A(x)) && InNewLeftContext(D(d)))\n"
                                        "  produce C(x * 10 + d); produce C(-1); }\n");
  EXPECT_EQ(derive_string(model), "E(1) D(7) C(17)");
}

// Interpretation rules test context in the string being interpreted; new
// context (there is no string being built: the turtle takes the modules) is false.
TEST(InBodyContext, InterpretationRules) {
  // A(1) B(2) C(3): B's left is A(1), right C(3) -> E(13); InNewLeftContext is false.
  const std::string model = write_model("interpretation",
                                        "derivation length: 0;\nAxiom: A(1) B(2) C(3);\n"
                                        "interpretation:\n"
                                        "A(x): { produce E(x); }\n"
                                        "B(y): { int a, c, e; if (InNewLeftContext(E(e))) produce D(e);\n"
                                        "  if (InLeftContext(A(a)) && InRightContext(C(c))) produce E(a * 10 + c);\n"
                                        "  produce D(-1); }\n");
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(model, options);
  simulation.run();
  EXPECT_EQ(io::format_string(simulation.interpreted(0), simulation.types()), "E(1) E(13) C(3)\n");
}

// ---- bad input ------------------------------------------------------------

// A variable whose type is not the module's parameter type does not bind; the
// error points at the variable in the .l file.
TEST(InBodyContext, WrongParameterTypeIsReportedAtTheVariable) {
  // Line 5 of the file (after the 4 header lines); "  if (InLeftContext(A(n)))": n at column 23.
  const std::string model = write_model("bad-type",
                                        "Axiom: A(1) B(0);\n"
                                        "B(y): { float n;\n"
                                        "  if (InLeftContext(A(n))) produce B(1);\n"
                                        "  produce B(2); }\n");
  const ProcessResult r = run_sylva({"run", model});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(model + ":7:23: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("float"), std::string::npos) << r.err;
}

// A pattern module with the wrong number of parameters.
TEST(InBodyContext, WrongParameterCountIsReportedAtTheModule) {
  // "  if (InRightContext(C(n, m))) ...": C at column 22 of line 7.
  const std::string model = write_model("bad-count",
                                        "Axiom: B(0) C(1);\n"
                                        "B(y): { int n, m;\n"
                                        "  if (InRightContext(C(n, m))) produce B(1);\n"
                                        "  produce B(2); }\n");
  const ProcessResult r = run_sylva({"run", model});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(model + ":7:22: error: module 'C' has 1 parameter but InRightContext names 2"),
            std::string::npos)
      << r.err;
}

// Outside a rule body there is no predecessor whose context could be tested.
TEST(InBodyContext, OnlyInRuleBodies) {
  const std::string in_start = write_model("in-start",
                                           "int x;\nStart: { if (InLeftContext(A(x))) x = 1; }\n"
                                           "Axiom: A(1);\n");
  const ProcessResult r = run_sylva({"run", in_start});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(in_start + ":6:14: error: 'InLeftContext' tests the context of a rule's predecessor"),
            std::string::npos)
      << r.err;

  const std::string in_function = write_model("in-function",
                                              "bool f() { int x; return InRightContext(A(x)); }\n"
                                              "Axiom: A(1);\n");
  const ProcessResult r2 = run_sylva({"run", in_function});
  EXPECT_NE(r2.exit_code, 0);
  EXPECT_NE(r2.err.find(in_function + ":5:26: error: 'InRightContext' tests"), std::string::npos) << r2.err;
}

}  // namespace
}  // namespace sylva::test
