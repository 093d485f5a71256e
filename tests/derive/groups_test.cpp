// Production groups (LPFG manual 4.4): group N: ... endgroup, UseGroup,
// CurrentGroup, and group 0 as the fallback, for productions, decomposition
// and interpretation rules. Expected strings are worked out by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "api/simulation.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test {
namespace {

std::string write_model(const std::string& test, const std::string& body) {
  return write_temp_file("groups-" + test, "model.l",
                         "#include <lpfgall.h>\nmodule A(int); module B(int); module C(int);\n" + body);
}

TEST(Groups, CurrentGroupFirstThenGroupZero) {
  // Step 1 in group 1: A has a group-1 rule (A(1)); B only a group-0 one (B(10)).
  // Step 2 in group 2: A falls back to group 0 (A(101)); B has a group-2 rule (B(12)).
  // Step 3 in group 0 (UseGroup(0)): only group 0: A(201), B(22).
  const std::string model = write_model("fallback",
                                        "int n;\nStart: { n = 0; }\n"
                                        "StartEach: { n++; UseGroup(n == 3 ? 0 : n); }\n"
                                        "derivation length: 3;\nAxiom: A(0) B(0);\n"
                                        "A(x): { produce A(x + 100); }\n"
                                        "B(x): { produce B(x + 10); }\n"
                                        "group 1:\nA(x): { produce A(x + 1); }\n"
                                        "group 2:\nB(x): { produce B(x + 2); }\n"
                                        "endgroup\n");
  EXPECT_EQ(derive_string(model, 1), "A(1) B(10)");
  EXPECT_EQ(derive_string(model, 2), "A(101) B(12)");
  EXPECT_EQ(derive_string(model, 3), "A(201) B(22)");
}

TEST(Groups, CurrentGroupInBodies) {
  // UseGroup in Start takes effect at the first step; a body reads it back.
  const std::string model = write_model("current",
                                        "Start: { UseGroup(3); }\nderivation length: 1;\nAxiom: A(0);\n"
                                        "group 3:\nA(x): { produce A(CurrentGroup()); }\nendgroup\n");
  EXPECT_EQ(derive_string(model), "A(3)");
}

TEST(Groups, DecompositionUsesTheCurrentGroup) {
  // The axiom is decomposed in group 0: group 1's rule does not apply -> A(0).
  // Step 1 in group 1: A(0) -> A(1) (group 0 production); decomposition in
  // group 1 -> B(1) C(1).
  const std::string model = write_model("decomposition",
                                        "Start: { UseGroup(1); }\nderivation length: 1;\nAxiom: A(0);\n"
                                        "A(x): { produce A(x + 1); }\n"
                                        "decomposition:\ngroup 1:\nA(x): { produce B(x) C(x); }\nendgroup\n");
  EXPECT_EQ(derive_string(model, 0), "A(0)");
  EXPECT_EQ(derive_string(model, 1), "B(1) C(1)");
}

TEST(Groups, InterpretationUsesTheCurrentGroup) {
  // After step 1 (group 2) A(0) is interpreted by group 2's rule, B by group 0's.
  const std::string model = write_model("interpretation",
                                        "Start: { UseGroup(2); }\nderivation length: 1;\nAxiom: A(0) B(0);\n"
                                        "interpretation:\n"
                                        "A(x): { produce C(0); }\nB(x): { produce C(5); }\n"
                                        "group 2:\nA(x): { produce C(2); }\nendgroup\n");
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(model, options);
  simulation.run();
  EXPECT_EQ(io::format_string(simulation.interpreted(0), simulation.types()), "C(2) C(5)\n");
}

TEST(Groups, EmptyGroupIsStillAGroup) {
  // group 4 has no rules: selecting it applies group 0's.
  const std::string model = write_model("empty",
                                        "Start: { UseGroup(4); }\nderivation length: 1;\nAxiom: A(0);\n"
                                        "A(x): { produce A(x + 1); }\ngroup 4:\nendgroup\n");
  EXPECT_EQ(derive_string(model), "A(1)");
}

// UseGroup of a group the model never defines does not stop lpfg: a number
// past its groups (0 to 3 here) is ignored, one inside them that no group
// declares (2) is selected and its step applies no productions. lpfg -b on
// this model: g1 in steps 1, 2 (7 ignored) and 4, nothing in step 3: A(30).
// Each is a warning at the call (line 6 and 7), once.
TEST(Groups, UndefinedGroupsAreWarningsAsInLpfg) {
  const std::string model = write_model("undefined",
                                        "int n;\nStart: { n = 0; }\n"
                                        "StartEach: { n++;\n"
                                        "  if (n == 2 || n == 5) UseGroup(7);\n"
                                        "  else if (n == 3) UseGroup(2); else UseGroup(1); }\n"
                                        "derivation length: 5;\nAxiom: A(0);\n"
                                        "A(x): { produce A(x + 1); }\n"
                                        "group 1:\nA(x): { produce A(x + 10); }\n"
                                        "group 3:\nA(x): { produce A(x + 100); }\nendgroup\n");
  const std::string dir = std::filesystem::path(model).parent_path().string();
  const std::string out = dir + "/out.txt";
  const ProcessResult r = run_sylva({"run", model, "--string", out});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(out), "A(40)\n");  // step 5 ignores 7 again: group 1
  const std::string ignored = model + ":6: warning: UseGroup(7) selects no group: the model's groups are 0 to 3";
  const std::string empty = model + ":7: warning: UseGroup(2) selects group 2, which the model does not declare";
  EXPECT_NE(r.err.find(ignored), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(ignored), r.err.rfind(ignored)) << "once: " << r.err;
  EXPECT_NE(r.err.find(empty), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sylva::test
