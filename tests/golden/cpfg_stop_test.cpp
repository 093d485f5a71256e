// cpfg's stop(n) (CPFG manual 5.6): the run ends after the step that calls it.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_support.h"

namespace sylva::test {
namespace {

// A --> AB adds one B a step; stop in the third step's EndEach leaves
// A and three Bs, though the derivation length is 10.
TEST(CpfgStop, EndsTheRunAfterTheStep) {
  for (const char* call : {"stop(1)", "stop(0)", "stop()"}) {
    const std::string dir = make_temp_dir("cpfg-stop");
    std::ofstream(dir + "/m.l") << "Lsystem: 1\n"
                                   "Start: { n = 0; }\n"
                                   "EndEach: { n = n + 1; if (n == 3) { "
                                << call
                                << "; } }\n"
                                   "derivation length: 10\nAxiom: A\nA --> AB\nendlsystem\n";
    ProcessResult r = run_sylva({"run", "m.l"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "ABBB\n") << call;
  }
}

}  // namespace
}  // namespace sylva::test
