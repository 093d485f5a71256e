// Ring L-systems (LPFG manual 3.1.4): the last and first modules of the
// string are neighbours for context matching, and so a branch may open
// before the end of the string and close after its start. Expected strings
// are worked out by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_support.h"

namespace sylva::test {
namespace {

std::string write_model(const std::string& test, const std::string& body) {
  return write_temp_file("ring-" + test, "model.l",
                         "#include <lpfgall.h>\nmodule C(int); module D(int); module H();\n" + body);
}

// The string  ] C(1) [ H D(5) ] C(2) [ H D(6)  read round the ring is
// C(1) [H D(5)] C(2) [H D(6)]: each C has the other as its neighbour on
// both sides, past the other's branch.
const char* kAxiom = "derivation length: 1;\nAxiom: ] C(1) [ H D(5) ] C(2) [ H D(6);\n";

TEST(RingContext, LeftContextSkipsBranchAcrossTheEnds) {
  // C(1): left is the ] at the start; its [ is the last one, after C(2) -> C(12).
  // C(2): left skips [H D(5)] -> C(1) -> C(21).
  EXPECT_EQ(derive_string(write_model("left", std::string("ring L-system: 1;\n") + kAxiom +
                                                  "C(l) < C(v): { produce C(v * 10 + l); }\n")),
            "EB C(12) SB H D(5) EB C(21) SB H D(6)");
}

TEST(RingContext, RightContextSkipsBranchAcrossTheEnds) {
  // C(1): skips [H D(5)] -> C(2) -> C(12). C(2): its branch [H D(6) runs past the
  // end and closes with the first ] -> C(1) -> C(21).
  EXPECT_EQ(derive_string(write_model("right", std::string("ring L-system: 1;\n") + kAxiom +
                                                   "C(v) > C(r): { produce C(v * 10 + r); }\n")),
            "EB C(12) SB H D(5) EB C(21) SB H D(6)");
}

TEST(RingContext, BranchEndIsNotContinuedAcrossTheEnds) {
  // D(5) and D(6) end their branches (D(6)'s ] comes after the ends): nothing
  // is to their right, so nothing changes.
  EXPECT_EQ(derive_string(write_model("branch-end", std::string("ring L-system: 1;\n") + kAxiom +
                                                        "D(d) > C(r): { produce D(0); }\n")),
            "EB C(1) SB H D(5) EB C(2) SB H D(6)");
  // Their left passes H (ignored) and the [ to the C they branch from.
  EXPECT_EQ(derive_string(write_model("branch-root", std::string("ignore: H;\nring L-system: 1;\n") + kAxiom +
                                                         "C(c) < D(d): { produce D(d * 10 + c); }\n")),
            "EB C(1) SB H D(51) EB C(2) SB H D(62)");
}

TEST(RingContext, WithoutRingTheEndsAreNotNeighbours) {
  // C(1): the ] at the start closes nothing -> no left context. C(2): C(1) -> C(21).
  EXPECT_EQ(derive_string(write_model("linear-left", std::string(kAxiom) +
                                                         "C(l) < C(v): { produce C(v * 10 + l); }\n")),
            "EB C(1) SB H D(5) EB C(21) SB H D(6)");
  // C(2): its branch never closes -> no right context. C(1): C(2) -> C(12).
  EXPECT_EQ(derive_string(write_model("linear-right", std::string(kAxiom) +
                                                          "C(v) > C(r): { produce C(v * 10 + r); }\n")),
            "EB C(12) SB H D(5) EB C(2) SB H D(6)");
}

// Matching goes across the ends of the ring at most once, so it never runs
// round for ever: a pattern longer than the ring does not match.
TEST(RingContext, ContextGoesAcrossTheEndsOnce) {
  // Ring C(1) C(2). Going left from C(2): C(1), across the ends C(2), C(1), then
  // the start again: four Cs never match. From C(1): C(2) (across), C(1), then the start.
  EXPECT_EQ(derive_string(write_model("once", "ring L-system: 1;\nderivation length: 1;\nAxiom: C(1) C(2);\n"
                                              "C(a) C(b) C(c) C(d) < C(v): { produce C(0); }\n"
                                              "C(b) < C(v): { produce C(v * 10 + b); }\n")),
            "C(12) C(21)");
}

}  // namespace
}  // namespace sylva::test
