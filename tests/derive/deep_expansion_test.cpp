// Decomposition and interpretation as deep as a model asks: a maximum depth
// of a million takes no machine stack, whether the successor to expand
// again is the last of its level (A --> B A) or not (A --> A B).
#include <gtest/gtest.h>

#include <string>

#include "api/simulation.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {

std::unique_ptr<Simulation> open(const std::string& name, const std::string& source) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  return std::make_unique<Simulation>(write_temp_file("deep-" + name, "deep.l", source), options,
                                      [](const std::string&) {});
}

std::string model(const std::string& block, int depth, const std::string& rule) {
  return "#include <lpfgall.h>\nmodule A(int);\nmodule B();\nderivation length: 0;\naxiom: A(0);\n" + block +
         ":\nmaximum depth: " + std::to_string(depth) + ";\n" + rule + "\n";
}

std::size_t count(const ModuleString& string, const Simulation& s) { return string.count_modules(s.types()); }

TEST(DeepExpansion, DecompositionAMillionLevelsDeepAtTheEndOfEachSuccessor) {
  auto s = open("tail", model("decomposition", 1000000, "A(n) : { if (n < 999999) produce B A(n + 1); produce B; }"));
  s->run();
  EXPECT_EQ(count(s->string(), *s), 1000000u);
}

TEST(DeepExpansion, DecompositionAHundredThousandLevelsDeepBeforeTheRestOfEachSuccessor) {
  auto s = open("head", model("decomposition", 100000, "A(n) : { if (n < 99999) produce A(n + 1) B; produce B; }"));
  s->run();
  EXPECT_EQ(count(s->string(), *s), 100000u);
}

TEST(DeepExpansion, SelfFeedingDecompositionStopsAtTheMaximumDepth) {
  for (int depth : {100000, 1000000}) {
    auto s = open("self-" + std::to_string(depth), model("decomposition", depth, "A(n) : { produce A(n + 1); }"));
    s->run();
    EXPECT_EQ(s->string_text(), "A(" + std::to_string(depth) + ")\n");
    ASSERT_FALSE(s->warnings().empty());
    EXPECT_NE(s->warnings().back().find("maximum decomposition depth (" + std::to_string(depth) + ") reached"),
              std::string::npos);
  }
}

TEST(DeepExpansion, InterpretationAMillionLevelsDeep) {
  auto tail = open("interpretation-tail",
                   model("interpretation", 1000000, "A(n) : { if (n < 999999) produce B A(n + 1); produce B; }"));
  tail->run();
  EXPECT_EQ(count(tail->interpreted(0), *tail), 1000000u);
  auto head = open("interpretation-head",
                   model("interpretation", 100000, "A(n) : { if (n < 99999) produce A(n + 1) B; produce B; }"));
  head->run();
  EXPECT_EQ(count(head->interpreted(0), *head), 100000u);
}

TEST(DeepExpansion, AComputedNegativeDepthIsAnError) {
  auto s = open("negative", "#include <lpfgall.h>\nmodule A();\nint Depth() { return -3; }\nderivation length: 0;\n"
                            "axiom: A;\ndecomposition:\nmaximum depth: Depth();\nA() : { produce A; }\n");
  try {
    s->run();
    FAIL() << "a negative depth was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("the maximum decomposition depth is negative (-3)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sylva::test
