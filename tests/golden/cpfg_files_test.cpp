// cpfg's file functions (CPFG manual 5.4): fopen, fscan, fprintf, fclose.
#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::test {
namespace {

// Start reads two numbers, the production uses their sum, End writes both and
// the count fscan returned: A(0) -> A(2.5 + 4) = A(6.5); out.txt "2.5 4 2".
TEST(CpfgFiles, ReadInStartWriteInEnd) {
  const std::string dir = make_temp_dir("cpfg-files");
  std::ofstream(dir + "/in.txt") << "2.5 4\n";
  std::ofstream(dir + "/m.l") << "Lsystem: 1\n"
                                 "Start: { f = fopen(\"in.txt\", \"r\"); n = fscan(f, \"%f %f\", &a, &b); fclose(f); }\n"
                                 "End: { g = fopen(\"out.txt\", \"w\"); fprintf(g, \"%g %g %g\\n\", a, b, n); "
                                 "fclose(g); }\n"
                                 "derivation length: 1\nAxiom: A(0)\nA(x) --> A(a+b)\nendlsystem\n";
  ProcessResult r = run_sylva({"run", "m.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "A(6.5)\n");
  EXPECT_EQ(read_text(dir + "/out.txt"), "2.5 4 2\n");
}

// A file that cannot be opened gives id 0, a message, and reads nothing.
TEST(CpfgFiles, MissingFileIsReportedAndReadsNothing) {
  const std::string dir = make_temp_dir("cpfg-files-missing");
  std::ofstream(dir + "/m.l") << "Lsystem: 1\n"
                                 "Start: { a = 7; f = fopen(\"absent.txt\", \"r\"); n = fscan(f, \"%f\", &a); }\n"
                                 "derivation length: 1\nAxiom: A(0)\nA(x) --> A(a+f)\nendlsystem\n";
  ProcessResult r = run_sylva({"run", "m.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "A(7)\n");
  EXPECT_NE(r.err.find("fopen: cannot open absent.txt"), std::string::npos) << r.err;
}

TEST(CpfgFiles, FileNameMustBeAString) {
  const std::string dir = make_temp_dir("cpfg-files-bad");
  std::ofstream(dir + "/m.l") << "Lsystem: 1\nStart: { f = fopen(3, \"r\"); }\n"
                                 "derivation length: 1\nAxiom: A(0)\nendlsystem\n";
  ProcessResult r = run_sylva({"run", "m.l"}, dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("m.l:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a file name in quotes"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sylva::test
