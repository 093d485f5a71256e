// Simulation as a front door drives it: step by step, rewound, run to an end,
// opened again with another -D value in the same process, with the model's
// requests acted on between its control statements.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "api/simulation.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// Fibonacci words: A -> A B, B -> A gives A, A B, A B A, A B A A B, ...
constexpr const char* kFibonacci =
    "#include <lpfgall.h>\n"
    "module A();\nmodule B();\n"
    "derivation length: 3;\n"
    "axiom: A;\n"
    "A() : { produce A B; }\n"
    "B() : { produce A; }\n";

std::unique_ptr<Simulation> open(const std::string& path, std::vector<std::string> defines = {},
                                 Simulation::MessageSink messages = [](const std::string&) {}) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.defines = std::move(defines);
  return std::make_unique<Simulation>(path, options, std::move(messages));
}

std::string text(const Simulation& s) {
  std::string t = s.string_text();
  if (!t.empty() && t.back() == '\n') t.pop_back();
  return t;
}

TEST(SimulationSteps, StepByStepThenRewindToTheAxiom) {
  auto s = open(write_temp_file("simulation-fibonacci", "fibonacci.l", kFibonacci));
  EXPECT_FALSE(s->begun());
  s->begin();
  EXPECT_EQ(s->step_number(), 0);
  EXPECT_EQ(text(*s), "A");
  const char* expected[] = {"A B", "A B A", "A B A A B", "A B A A B A B A"};
  for (int k = 0; k < 4; ++k) {  // past the derivation length: a front door decides when to stop
    ASSERT_TRUE(s->step());
    EXPECT_EQ(s->step_number(), k + 1);
    EXPECT_EQ(text(*s), expected[k]);
  }
  EXPECT_EQ(s->step_seconds().size(), 4u);
  s->finish();
  EXPECT_TRUE(s->finished());
  EXPECT_FALSE(s->step()) << "a finished run takes no more steps";

  s->rewind();
  EXPECT_EQ(s->step_number(), 0);
  s->begin();
  EXPECT_EQ(s->step_number(), 0);
  EXPECT_EQ(text(*s), "A");
  EXPECT_TRUE(s->step_seconds().empty());
}

TEST(SimulationSteps, RunGoesToTheDerivationLengthAndKeepsARunThatEndedThere) {
  auto s = open(write_temp_file("simulation-fibonacci-run", "fibonacci.l", kFibonacci));
  s->run();
  EXPECT_EQ(s->derivation_length(), 3);
  EXPECT_EQ(s->step_number(), 3);
  EXPECT_EQ(text(*s), "A B A A B");
  s->run(3);  // already there: nothing derived again
  EXPECT_EQ(s->step_seconds().size(), 3u);
  s->run(1);  // elsewhere: from the axiom
  EXPECT_EQ(text(*s), "A B");
  // A run in progress goes on from where it is.
  s->rewind();
  s->begin();
  s->step();
  s->run(2);
  EXPECT_EQ(s->step_seconds().size(), 2u);
  EXPECT_EQ(text(*s), "A B A");
}

TEST(SimulationSteps, StopEndsTheRun) {
  auto s = open(write_temp_file("simulation-stop", "stop.l",
                                "#include <lpfgall.h>\nmodule A(int);\nderivation length: 10;\naxiom: A(0);\n"
                                "EndEach: { if (StepNo() == 2) Stop(); }\n"
                                "A(n) : { produce A(n+1); }\n"));
  s->run();
  EXPECT_TRUE(s->stopped());
  EXPECT_EQ(s->step_number(), 2);
  EXPECT_EQ(text(*s), "A(2)");
  EXPECT_FALSE(s->step());
  s->rewind();
  EXPECT_FALSE(s->stopped());
  EXPECT_TRUE(s->step()) << "a rewound run steps again";
  EXPECT_EQ(text(*s), "A(1)");
}

// The studio's edit loop: the same model opened again with another value,
// both loaded at once.
TEST(SimulationSteps, OpenedAgainWithAnotherDefine) {
  const std::string model = write_temp_file("simulation-define", "define.l",
                                            "#include <lpfgall.h>\n#ifndef START\n#define START 1\n#endif\n"
                                            "module A(int);\nderivation length: 1;\naxiom: A(START);\n"
                                            "A(n) : { produce A(n*10); }\n");
  auto first = open(model, {"START=5"});
  auto second = open(model, {"START=7"});
  first->run();
  second->run();
  EXPECT_EQ(text(*first), "A(50)");
  EXPECT_EQ(text(*second), "A(70)");
}

TEST(SimulationSteps, EachWarningIsKeptOnce) {
  std::string told;
  auto s = open(write_temp_file("simulation-warnings", "warnings.l",
                                "#include <lpfgall.h>\nmodule A();\nderivation length: 3;\naxiom: A;\n"
                                "StartEach: { UseGroup(7); }\n"),
                {}, [&](const std::string& text) { told += text; });
  s->run();
  ASSERT_EQ(s->warnings().size(), 1u) << told;
  EXPECT_NE(s->warnings()[0].find("UseGroup(7)"), std::string::npos) << s->warnings()[0];
}

// OutputString in StartEach writes the string as it is before the step's
// productions: requests are acted on as each control statement returns.
TEST(SimulationRequests, OutputStringInStartEachSeesTheStringBeforeTheStep) {
  const std::string dir = make_temp_dir("simulation-output-string");
  auto s = open(write_temp_file("simulation-output-string-model", "model.l",
                                std::string("#include <lpfgall.h>\nmodule A();\nmodule B();\nderivation length: 2;\n"
                                            "axiom: A;\nStartEach: { if (StepNo() == 2) OutputString(\"") +
                                    dir + "/before-2.str\"); }\nA() : { produce A B; }\n"));
  s->run();
  EXPECT_EQ(read_text(dir + "/before-2.str"), "A B\n");
}

TEST(SimulationRequests, LoadStringInAProductionIsAnError) {
  auto s = open(write_temp_file("simulation-load-in-rule", "model.l",
                                "#include <lpfgall.h>\nmodule A();\nderivation length: 1;\naxiom: A;\n"
                                "A() : { LoadString(\"x.str\"); produce A; }\n"));
  try {
    s->run();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("LoadString may only be called in a control statement"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sylva::test
