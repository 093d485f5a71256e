// The communication library's text, as the built-in programs see it and as
// lpfg and cpfg take their answers back (libs/comm, lpfg/environment.cpp,
// lpfg/lengine.cpp InsertReadData, cpfg/interpret.c SetCommModulePars).
// Expected values are worked by hand from printf's formats.
#include <gtest/gtest.h>

#include <functional>

#include "env/comm_library_transport.h"
#include "env/comm_spec.h"

namespace sylva::env {
namespace {

// Remembers what it was sent and answers what `reply` says.
class Probe : public Field {
 public:
  explicit Probe(std::function<void(std::size_t, Answer&)> reply) : reply_(std::move(reply)) {}
  void answer(std::span<const Query> queries, std::span<Answer> answers, int) override {
    seen.assign(queries.begin(), queries.end());
    for (std::size_t k = 0; k < answers.size(); ++k) reply_(k, answers[k]);
  }
  std::vector<Query> seen;

 private:
  std::function<void(std::size_t, Answer&)> reply_;
};

Query module(const std::string& symbol, std::vector<float> parameters, std::array<float, 3> position) {
  Query q;
  q.module = {symbol, std::move(parameters)};
  q.turtle.position = position;
  q.turtle.position_count = 3;
  return q;
}

struct Exchange {
  std::vector<Query> seen;
  std::vector<Answer> answers;
  std::string warnings;
};

Exchange exchange(const std::string& e_file, ModelingProgram master, std::vector<Query> queries,
        std::function<void(std::size_t, Answer&)> reply) {
  auto probe = std::make_unique<Probe>(std::move(reply));
  Probe* seen = probe.get();
  Exchange result;
  auto field = through_comm_library(std::move(probe), parse_comm_spec(e_file, "x.e"), master,
                                    [&](const std::string& text) { result.warnings += text; });
  result.answers.resize(queries.size());
  field->answer(queries, result.answers, 0);
  result.seen = seen->seen;
  return result;
}

TEST(CommLibraryTransport, ParametersTravelAsLpfgAndCpfgPrintThem) {
  const std::string e = "executable: honda81 x.spec\nturtle position: %f %f %f\n";
  auto nothing = [](std::size_t, Answer&) {};
  // lpfg: "%f", six decimals.
  Exchange lpfg = exchange(e, ModelingProgram::lpfg, {module("E1", {0.1234567f}, {0, 0, 0})}, nothing);
  EXPECT_EQ(lpfg.seen[0].module.parameters[0], 0.123457f);
  EXPECT_EQ(exchange(e, ModelingProgram::lpfg, {module("E1", {1e-7f}, {0, 0, 0})}, nothing).seen[0].module.parameters[0],
            0.0f);
  // cpfg: "%g", six significant digits.
  Exchange cpfg = exchange(e, ModelingProgram::cpfg, {module("?E", {123.4567f, 1e-7f}, {0, 0, 0})}, nothing);
  EXPECT_EQ(cpfg.seen[0].module.parameters[0], 123.457f);
  EXPECT_EQ(cpfg.seen[0].module.parameters[1], 1e-7f);
}

TEST(CommLibraryTransport, TheTurtleTravelsThroughTheFormat) {
  auto nothing = [](std::size_t, Answer&) {};
  // The text before the first conversion is skipped; "%.1f" rounds.
  Exchange rounded = exchange("executable: a\nturtle position: P: %.1f %.1f %.1f\n", ModelingProgram::cpfg,
                    {module("?E", {1}, {1.26f, -0.04f, 2.5f})}, nothing);
  EXPECT_EQ(rounded.seen[0].turtle.position, (std::array<float, 3>{1.3f, -0.0f, 2.5f}));
  // Two conversions: the third value is what sscanf left, the previous
  // query's (0 at first).
  Exchange two = exchange("executable: a\nturtle position: %g %g\n", ModelingProgram::cpfg,
                {module("?E", {1}, {1, 2, 3}), module("?E", {1}, {4, 5, 6})}, nothing);
  EXPECT_EQ(two.seen[0].turtle.position, (std::array<float, 3>{1, 2, 0}));
  EXPECT_EQ(two.seen[1].turtle.position, (std::array<float, 3>{4, 5, 0}));
}

TEST(CommLibraryTransport, LpfgTakesOneValueForE1TwoForE2AndUpToTwentyForEa20) {
  const std::string e = "executable: a\nturtle position: %f %f %f\n";
  // Every module is answered p1 = 0.1234567 (and p3 = 2 for the third).
  auto reply = [](std::size_t k, Answer& a) {
    a.assign(0, 0.1234567f);
    if (k == 2) a.assign(2, 2);
  };
  Exchange r = exchange(e, ModelingProgram::lpfg,
              {module("E1", {5}, {0, 0, 0}), module("E2", {5, 6}, {0, 0, 0}),
               module("EA20", std::vector<float>(20, 7), {0, 0, 0})},
              reply);
  EXPECT_EQ(r.answers[0].set.count(), 1u);
  EXPECT_EQ(r.answers[0].value[0], 0.123457f);  // "%g"
  EXPECT_TRUE(r.answers[1].set.none());          // one value for an E2: dropped
  // Three values for the EA20; the unanswered second is written as 0.
  EXPECT_EQ(r.answers[2].set.count(), 3u);
  EXPECT_EQ(r.answers[2].value[1], 0.0f);
  EXPECT_EQ(r.answers[2].value[2], 2.0f);
  EXPECT_NE(r.warnings.find("warning: 1 answer of the environmental program ignored in the pass before step 1"),
            std::string::npos)
      << r.warnings;
}

TEST(CommLibraryTransport, CpfgWritesTheValuesSetWhereTheModuleHasRoom) {
  auto reply = [](std::size_t, Answer& a) {
    a.assign(0, 1.5f);
    a.assign(2, 3.25f);
  };
  Exchange r = exchange("executable: a\nturtle position: %f %f %f\n", ModelingProgram::cpfg,
              {module("?E", {0, 0, 0}, {0, 0, 0}), module("?E", {0, 0}, {0, 0, 0})}, reply);
  EXPECT_EQ(r.answers[0].set.count(), 2u);  // p2 was not set: left alone
  EXPECT_FALSE(r.answers[0].set[1]);
  EXPECT_EQ(r.answers[1].set.count(), 1u);  // no room for p3
  EXPECT_NE(r.warnings.find("1 answer"), std::string::npos);
}

}  // namespace
}  // namespace sylva::env
