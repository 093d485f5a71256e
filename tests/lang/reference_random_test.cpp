// Random numbers as the reference programs draw them, where a model leaves
// them unseeded or asks for normal variates. Expected strings are what the
// reference lpfg (Printf of each value) and cpfg (-str) printed for these
// models; the first ran() values are also drand48's from the state
// {0x330E, 0, 0}: 0.170828036, 0.749901980, 0.0963716556.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "test_support.h"

namespace sylva::test {
namespace {

// lpfg's ran() starts from drand48's state after srand48(0) (lpfg's
// interface.cpp: main_xsubi = {0x330E, 0, 0}), not from drand48's default.
TEST(ReferenceRandom, LpfgRanStartsAsSrand48OfZero) {
  const std::string model = write_temp_file("random-lpfg", "r.l", R"(#include <lpfgall.h>
module A(float);
derivation length: 0;
Axiom: A(ran(1)) A(ran(1)) A(ran(10));
)");
  // The values lpfg printed (with 9 digits), as floats: the string holds
  // each in its shortest exact text.
  const std::string text = derive_string(model);
  const float expected[] = {0.17082803f, 0.74990201f, 0.963716567f};
  const char* at = text.c_str();
  for (float value : expected) {
    at = std::strchr(at, '(');
    ASSERT_NE(at, nullptr) << text;
    EXPECT_EQ(std::strtof(at + 1, nullptr), value) << text;
    ++at;
  }
  EXPECT_EQ(std::strchr(at, '('), nullptr) << text;
}

// cpfg's nran keeps the second value of each pair of the polar method for
// the next call, and starts with a kept value of 0: the first call of a run
// gives the mean. srand() empties it. ran() draws from the same generator.
TEST(ReferenceRandom, CpfgNranIsThePolarMethodWithAKeptValue) {
  const std::string unseeded = write_temp_file("random-cpfg", "n.l",
                                               "Lsystem: 1\nderivation length: 1\nAxiom: A(0)\n"
                                               "A(x) --> B(nran(5,1))B(nran(5,1))B(nran(5,1))B(ran(1))\nendlsystem\n");
  ProcessResult run = run_sylva({"run", unseeded});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "B(5)B(5.52779)B(4.30479)B(0.0963717)\n");
  const std::string seeded = write_temp_file("random-cpfg-seeded", "s.l",
                                             "Lsystem: 1\nderivation length: 1\nAxiom: A(0)\n"
                                             "A(x) : 1 {srand(7);} --> B(nran(5,1))B(nran(5,1))B(nran(5,1))\n"
                                             "endlsystem\n");
  run = run_sylva({"run", seeded});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "B(5.88987)B(3.85827)B(4.38923)\n");
}

}  // namespace
}  // namespace sylva::test
