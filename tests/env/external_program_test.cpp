// Environmental programs run as separate processes: the Enviro manual's
// example programs built against the sylva_comm library drive cpfg models
// (expected strings worked out by hand), and programs that die, hang, answer
// garbage or cannot be found fail with an error naming them, never a hang.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "api/simulation.h"
#include "env/comm_spec.h"
#include "env/environment.h"
#include "env/external_program.h"
#include "io/string_text.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {

struct Folder {
  std::string dir;
  std::string file(const std::string& name, const std::string& text) const {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  std::string script(const std::string& name, const std::string& body) const {
    const std::string path = file(name, "#!/bin/sh\n" + body);
    ::chmod(path.c_str(), 0755);
    return path;
  }
};

std::string derive_with_environment(const std::string& model, const std::string& e_file, int steps) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.input_files = {e_file};
  Simulation s(model, options);
  s.run(steps);
  std::string text = io::format_string(s.string(), s.types());
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

// The Sierpinski triangle of EnviroManual 4.3.2. Each ?E(0) grows two
// branches, to the turtle's left-forward ("[F?E(0)]": along H) and, after
// -(60)/(180), 60 degrees to the right with the frame rolled over, so that
// there the next -(60) turns back to the first direction. With H0 = (0,1) and
// H1 = (0.866,0.5), a ?E reached with frame A (H = H0) has children at +H0
// (frame A) and +H1 (frame B); one reached with frame B has them at +H1
// (frame B) and +H0 (frame A).
// The program answers in a pass before each step, so the ?E a step makes
// are 0 in the string it leaves:
//   step 1: ?E at (0,1) A and (0.866,0.5) B: apart, all stay 0.
//   step 2: (0,2) and (0.866,1.5) from the first; (1.732,1) and (0.866,1.5)
//           from the second: the pass before step 3 finds the two at
//           (0.866,1.5) and sets them to 1.
//   step 3: the ?E(1) do not grow; (0,2) A gives (0,3), (0.866,2.5);
//           (1.732,1) B gives (2.598,1.5), (1.732,2): no collision.
//   step 4: (0,3) A: (0,4), (0.866,3.5); (0.866,2.5) B: (1.732,3), (0.866,3.5);
//           (2.598,1.5) B: (3.464,2), (2.598,2.5); (1.732,2) A: (1.732,3),
//           (2.598,2.5), 0 until a fifth pass.
TEST(ExternalProgram, DelayedAnswerDrawsASierpinskiTriangle) {
  const Folder f{make_temp_dir("env-sierpinski")};
  const std::string model = f.file("sierpinski.l",
                                   "Lsystem: 1\nderivation length: 4\nAxiom: ?E(0)\n"
                                   "?E(c) : c==0 --> [F?E(0)]-(60)/(180)[F?E(0)]\nendlsystem\n");
  const std::string e_file = f.file("sierpinski.e", std::string("executable: ") + SYLVA_TEST_DELAYED_ANSWER +
                                                        " -e sierpinski.e\ncommunication type: pipes\n"
                                                        "turtle position: %g %g %g\n");
  auto pair = [](const char* a, const char* b) {
    return std::string("[F?E(") + a + ")]-(60)/(180)[F?E(" + b + ")]";
  };
  EXPECT_EQ(derive_with_environment(model, e_file, 1), pair("0", "0"));
  const std::string step2 = "[F" + pair("0", "0") + "]-(60)/(180)[F" + pair("0", "0") + "]";
  EXPECT_EQ(derive_with_environment(model, e_file, 2), step2);
  const std::string grown3 = "[F" + pair("0", "0") + "]-(60)/(180)[F?E(1)]";
  EXPECT_EQ(derive_with_environment(model, e_file, 3), "[F" + grown3 + "]-(60)/(180)[F" + grown3 + "]");
  const std::string grown4 =
      "[F[F" + pair("0", "0") + "]-(60)/(180)[F" + pair("0", "0") + "]]-(60)/(180)[F?E(1)]";
  EXPECT_EQ(derive_with_environment(model, e_file, 4), "[F" + grown4 + "]-(60)/(180)[F" + grown4 + "]");
}

// EnviroManual 4.3.1: 1 where the turtle is farther from the origin than the
// parameter, else 0. The three ?E are at distances 0, 1 and 2: the pass
// before step 1 compares them with 0.5, 2 and 1.5; the pass before step 2
// (no productions) with those answers, 0, 0 and 1.
TEST(ExternalProgram, ImmediateAnswerThroughCSMainLoop) {
  const Folder f{make_temp_dir("env-immediate")};
  const std::string model =
      f.file("distance.l", "Lsystem: 1\nderivation length: 2\nAxiom: ?E(0.5)F(1)?E(2)F(1)?E(1.5)\nendlsystem\n");
  const std::string e_file = f.file("distance.e", std::string("executable: ") + SYLVA_TEST_IMMEDIATE_ANSWER +
                                                      "\ncommunication type: pipes\nturtle position: %g %g %g\n");
  EXPECT_EQ(derive_with_environment(model, e_file, 0), "?E(0.5)F(1)?E(2)F(1)?E(1.5)");  // no step, no pass
  EXPECT_EQ(derive_with_environment(model, e_file, 1), "?E(0)F(1)?E(0)F(1)?E(1)");
  EXPECT_EQ(derive_with_environment(model, e_file, 2), "?E(0)F(1)?E(1)F(1)?E(1)");
}

// ---- failures, straight through the Field ----------------------------------------

env::CommSpec spec_for(const Folder& f, const std::string& executable) {
  return env::parse_comm_spec("executable: " + executable + "\ncommunication type: pipes\n", f.dir + "/plant.e");
}

std::string failure(const env::CommSpec& spec, double timeout = 5) {
  try {
    std::unique_ptr<env::Field> field = env::make_field(spec, [&] { env::FieldOptions o; o.timeout_seconds = timeout; return o; }());
    env::Query q;
    q.id = 4;
    q.module = env::ModuleRecord{"?E", {1}};
    std::vector<env::Query> queries{q};
    std::vector<env::Answer> answers(1);
    field->answer(queries, answers, 1);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "(no error)";
}

// A shell program that reads the header and says it is ready, then `rest`.
std::string ready_then(const std::string& rest) {
  return "while read line; do [ \"$line\" = end-header ] && break; done\necho ready\n" + rest;
}

TEST(ExternalProgram, AProgramThatDiesIsNamed) {
  const Folder f{make_temp_dir("env-dies")};
  f.script("dies", ready_then("exit 3\n"));
  EXPECT_EQ(failure(spec_for(f, "./dies")),
            f.dir + "/plant.e:1: error: environmental program './dies' exited with status 3 during the "
                    "environmental pass before step 2");
}

TEST(ExternalProgram, AProgramThatHangsIsStopped) {
  const Folder f{make_temp_dir("env-hangs")};
  f.script("hangs", ready_then("exec sleep 60\n"));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(failure(spec_for(f, "./hangs"), 0.5),
            f.dir + "/plant.e:1: error: environmental program './hangs' did not answer within 0.5 seconds during "
                    "the environmental pass before step 2 (it was stopped; --env-timeout sets the limit)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(ExternalProgram, GarbageIsRefused) {
  const Folder f{make_temp_dir("env-garbage")};
  f.script("garbage", ready_then("echo 'hello world'\necho end\ncat > /dev/null\n"));
  EXPECT_EQ(failure(spec_for(f, "./garbage")),
            f.dir + "/plant.e:1: error: environmental program './garbage' answered 'hello world' during the "
                    "environmental pass before step 2; expected 'ID INDEX VALUE' (INDEX from 0 to 19) or 'end'");
  f.script("stranger", ready_then("echo '99 0 1'\necho end\ncat > /dev/null\n"));
  EXPECT_EQ(failure(spec_for(f, "./stranger")),
            f.dir + "/plant.e:1: error: environmental program './stranger' answered module 99, which was not "
                    "asked about, during the environmental pass before step 2");
  f.script("chatty", "echo hello\ncat > /dev/null\n");
  EXPECT_EQ(failure(spec_for(f, "./chatty")),
            f.dir + "/plant.e:1: error: environmental program './chatty' sent 'hello' instead of 'ready' (is it "
                    "built with the sylva_comm library, and does it write nothing else to its standard output?)");
}

// lpfg and cpfg go on without an environment they cannot start: a warning
// at the executable: line says why, and nothing answers.
TEST(ExternalProgram, AnUnknownProgramIsIgnoredWithAWarningAtTheLine) {
  const Folder f{make_temp_dir("env-unknown")};
  auto warning_for = [&](const std::string& executable) {
    std::string warnings;
    env::FieldOptions options;
    options.warn = [&](const std::string& text) { warnings += text; };
    std::unique_ptr<env::Field> field = env::make_field(spec_for(f, executable), options);
    std::vector<env::Query> queries(1);
    std::vector<env::Answer> answers(1);
    field->answer(queries, answers, 1);
    EXPECT_TRUE(answers[0].set.none());
    return warnings;
  };
  EXPECT_EQ(warning_for("no-such-environment-program par.txt"),
            f.dir + "/plant.e:1:13: warning: environmental program 'no-such-environment-program' not found: not a "
                    "built-in program (honda81, ecosystem, arvo, density, clover, chiba, takenaka), not on PATH "
                    "and not in " + f.dir + "; the environment is ignored, as lpfg and cpfg ignore a program they "
                    "cannot start\n");
  EXPECT_EQ(warning_for("./missing"),
            f.dir + "/plant.e:1:13: warning: environmental program './missing' not found: no executable file " +
                f.dir + "/./missing; the environment is ignored, as lpfg and cpfg ignore a program they cannot "
                "start\n");
}

TEST(ExternalProgram, AnAnswerForAMissingParameterIsNamed) {
  const Folder f{make_temp_dir("env-missing-parameter")};
  f.script("beyond", ready_then("while read line; do case \"$line\" in\n"
                                "  query*) set -- $line; echo \"$2 1 7\" ;;\n  end) echo end ;;\nesac; done\n"));
  EXPECT_EQ(failure(spec_for(f, "./beyond")),
            f.dir + "/plant.e:1: error: environmental program './beyond' answered parameter 1 of module 4 (?E), "
                    "which has 1 parameter, during the environmental pass before step 2");
}

// A program that answers every pass at once; `timeout` would overflow the
// clock's ticks were it added to the time.
TEST(ExternalProgram, AHugeTimeoutIsNoTimeout) {
  const Folder f{make_temp_dir("env-huge-timeout")};
  f.script("quick", ready_then("while read line; do [ \"$line\" = end ] && echo end; done\n"));
  EXPECT_EQ(failure(spec_for(f, "./quick"), 1e16), "(no error)");
  EXPECT_EQ(failure(spec_for(f, "./quick"), 1e300), "(no error)");
}

// A program may send "end" as soon as a pass begins. A pass larger than a
// pipe holds (5000 queries with their positions: about 150 KB) must still be
// written whole, or the next pass's "begin" lands in the middle of a line and
// the program never sees it. The program answers the first E1 (id 1, after
// the F; the axiom has none) with the step and logs each "begin" it reads.
TEST(ExternalProgram, AnEarlyEndDoesNotCutTheRestOfAPass) {
  const Folder f{make_temp_dir("env-early-end")};
  const std::string model = f.file("big.l", R"(#include <lpfgall.h>
module A(int);
derivation length: 3;
axiom: A(0);
A(x) : {
  if (x == 0) { for (int i = 0; i < 5000; ++i) { nproduce F(1) E1(i); } produce A(1); }
  else produce A(x + 1);
}
)");
  const std::string log = f.dir + "/begins.log";
  f.script("early", "while IFS= read -r line; do case \"$line\" in\n"
                    "  end-header) echo ready ;;\n"
                    "  'begin 0') echo \"$line\" >> " + log + "; echo end ;;\n"
                    "  begin*) echo \"$line\" >> " + log + "; set -- $line; echo \"1 0 $2\"; echo end ;;\n"
                    "esac; done\n");
  const std::string e_file =
      f.file("early.e", "executable: ./early\ncommunication type: pipes\nturtle position: %g %g %g\n");
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.input_files = {e_file};
  options.environment.timeout_seconds = 10;
  Simulation s(model, options);
  s.run();
  const std::string text = io::format_string(s.string(), s.types());
  EXPECT_EQ(text.substr(0, 15), "F(1) E1(2) F(1)");  // answered in the pass before step 3
  std::ifstream in(log);
  const std::string begins((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(begins, "begin 0\nbegin 1\nbegin 2\n");
}

TEST(ExternalProgram, ThePassIsSentAsDocumented) {
  env::CommSpec spec = env::parse_comm_spec(
      "executable: x\ncommunication type: pipes\nturtle position: P:%.1f %.1f\nturtle line width: %g\n"
      "following module: yes\n",
      "plant.e");
  env::Query q;
  q.id = 7;
  q.module = env::ModuleRecord{"E2", {1.5f, 0}};
  q.following = env::ModuleRecord{"A", {2}};
  q.turtle.position = {0.25f, -3, 9};
  q.turtle.line_width = 2;
  env::Query last;
  last.id = 9;
  last.module = env::ModuleRecord{"E1", {0}};
  const std::vector<env::Query> queries{q, last};
  EXPECT_EQ(env::ExternalProgramField::encode_pass(queries, spec, 3),
            "begin 3\n"
            "query 7 E2 2 1.5 0\nposition P:0.2 -3.0\nline-width 2\nfollowing A 1 2\n"
            "query 9 E1 1 0\nposition P:0.0 0.0\nline-width 0\nfollowing\n"
            "end\n");
}

}  // namespace
}  // namespace sylva::test
