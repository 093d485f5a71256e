// The environmental pass: queries at every communication module with the
// turtle there (positions worked out by hand from the turtle's rules), the
// field called once per pass before each step (lpfg's and cpfg's Derive
// begin with it), answers written into E1, E2, EA20 and cpfg's ?E,
// Environment()/NoEnvironment() and --clean-ea20.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "env/field.h"
#include "io/string_text.h"
#include "support/diagnostic.h"
#include "sylva/predefined_ids.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// Records every pass and answers each query with the turtle's state:
// parameter 0..2 the position, 3..5 the heading, 6..8 left, 9..11 up, 12 the
// line width, 13 the scale factor (as many as the module has parameters).
class EchoField : public env::Field {
 public:
  void answer(std::span<const env::Query> queries, std::span<env::Answer> answers, int step) override {
    steps.push_back(step);
    passes.emplace_back(queries.begin(), queries.end());
    for (std::size_t k = 0; k < queries.size(); ++k) {
      const env::TurtleReport& t = queries[k].turtle;
      std::vector<float> values;
      for (const std::array<float, 3>* v : {&t.position, &t.heading, &t.left, &t.up})
        values.insert(values.end(), v->begin(), v->end());
      values.push_back(t.line_width);
      values.push_back(t.scale_factor);
      const std::size_t count = std::min(values.size(), queries[k].module.parameters.size());
      for (std::size_t i = 0; i < count; ++i) answers[k].assign(static_cast<int>(i), values[i]);
    }
  }
  void finish() override { ++finished; }

  std::vector<int> steps;
  std::vector<std::vector<env::Query>> passes;
  int finished = 0;
};

// Answers parameter 0 of every query with 10 times the step.
class StepField : public env::Field {
 public:
  void answer(std::span<const env::Query>, std::span<env::Answer> answers, int step) override {
    steps.push_back(step);
    for (env::Answer& a : answers) a.assign(0, 10.0f * static_cast<float>(step));
  }
  std::vector<int> steps;
};

std::string write_model(const std::string& name, const std::string& text) {
  return write_temp_file("env-pass-" + name, name + ".l", text);
}

SimulationOptions options_with(std::shared_ptr<env::Field> field) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.environment.field = std::move(field);
  return options;
}

// The string in the text format, without the newline.
std::string string_of(Simulation& s) {
  std::string text = io::format_string(s.string(), s.types());
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

void expect_vector(const std::array<float, 3>& actual, std::array<float, 3> expected) {
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << "component " << i;
}

// The parameters of the first module `id` in the string, as floats.
std::vector<float> parameters_of(const Simulation& d, ModuleId id) {
  const StringView v = d.string().view(d.types());
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    if (v.id_at(at) != id) continue;
    std::vector<float> out(d.types()[id].param_size / sizeof(float));
    std::memcpy(out.data(), module_params(v.data, at), out.size() * sizeof(float));
    return out;
  }
  return {};
}

void expect_floats(const std::vector<float>& actual, const std::vector<float>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << "parameter " << i;
}

constexpr const char* kLcModel = R"(#include <lpfgall.h>
EA20Array sevens() { EA20Array a; for (int i = 0; i < 20; ++i) a[i] = 7; return a; }
derivation length: 1;
axiom: Left(90) F(1) E1(5) Right(90) F(2) E2(0,0) SetWidth(3) EA20(sevens()) F(1);
)";

// Left(90) turns H to (-1,0,0), so F(1) ends at (-1,0,0): E1 is there.
// Right(90) turns back to H = (0,1,0), F(2) ends at (-1,2,0): E2 and EA20
// are there, with the initial frame H (0,1,0), L (-1,0,0), U (0,0,1).
TEST(EnvironmentPass, QueriesCarryTheTurtleAndTheFollowingModule) {
  auto field = std::make_shared<EchoField>();
  Simulation s(write_model("queries", kLcModel), options_with(field));
  s.run();
  ASSERT_EQ(field->steps, (std::vector<int>{0}));  // before the one step: none after it
  const std::vector<env::Query>& q = field->passes[0];  // the axiom as written
  ASSERT_EQ(q.size(), 3u);

  EXPECT_EQ(q[0].id, 2u);  // the module's place in the string
  EXPECT_EQ(q[0].module.symbol, "E1");
  EXPECT_EQ(q[0].module.parameters, std::vector<float>{5});
  expect_vector(q[0].turtle.position, {-1, 0, 0});
  expect_vector(q[0].turtle.heading, {-1, 0, 0});
  expect_vector(q[0].turtle.left, {0, -1, 0});
  EXPECT_EQ(q[0].following.symbol, "Right");
  EXPECT_EQ(q[0].following.parameters, std::vector<float>{90});

  EXPECT_EQ(q[1].id, 5u);
  EXPECT_EQ(q[1].module.symbol, "E2");
  expect_vector(q[1].turtle.position, {-1, 2, 0});
  EXPECT_EQ(q[1].following.symbol, "SetWidth");

  EXPECT_EQ(q[2].id, 7u);
  EXPECT_EQ(q[2].module.symbol, "EA20");
  EXPECT_EQ(q[2].module.parameters, std::vector<float>(20, 7.0f));
  expect_vector(q[2].turtle.heading, {0, 1, 0});
  expect_vector(q[2].turtle.left, {-1, 0, 0});
  expect_vector(q[2].turtle.up, {0, 0, 1});
  EXPECT_FLOAT_EQ(q[2].turtle.line_width, 3);
  EXPECT_FLOAT_EQ(q[2].turtle.scale_factor, 1);
  EXPECT_EQ(q[2].following.symbol, "F");
  // Without a .e file every field is sent in full.
  EXPECT_EQ(q[2].turtle.position_count, 3);
  EXPECT_EQ(q[2].turtle.line_width_count, 1);

  // The answers, in the string: E1 takes x, E2 x and y, EA20 all fourteen
  // values, keeping its own 7s after them.
  const Simulation& d = s;
  expect_floats(parameters_of(d, rt::mid::E1), {-1});
  expect_floats(parameters_of(d, rt::mid::E2), {-1, 2});
  expect_floats(parameters_of(d, rt::mid::EA20), {-1, 2, 0, 0, 1, 0, -1, 0, 0, 0, 0, 1, 3, 1, 7, 7, 7, 7, 7, 7});
  EXPECT_EQ(field->finished, 0);
}

TEST(EnvironmentPass, CleanEa20ZeroesWhatIsNotAnswered) {
  auto field = std::make_shared<EchoField>();
  SimulationOptions options = options_with(field);
  options.environment.clean_ea20 = true;
  Simulation s(write_model("clean", kLcModel), options);
  s.run();
  expect_floats(parameters_of(s, rt::mid::EA20),
                {-1, 2, 0, 0, 1, 0, -1, 0, 0, 0, 0, 1, 3, 1, 0, 0, 0, 0, 0, 0});
}

TEST(EnvironmentPass, TheFieldIsToldToFinishWithTheSimulation) {
  auto field = std::make_shared<EchoField>();
  {
    Simulation s(write_model("finish", kLcModel), options_with(field));
    s.run();
  }
  EXPECT_EQ(field->finished, 1);
}

// A .e file decides what is sent even when the embedding program brings the
// field (its executable: is then not started).
TEST(EnvironmentPass, TheCommFileSetsTheCounts) {
  const std::string model = write_model("counts", kLcModel);
  const std::string e_file = model.substr(0, model.rfind('/')) + "/plant.e";
  std::ofstream(e_file) << "executable: not-started\ncommunication type: pipes\nturtle position: %g %g\n";
  auto field = std::make_shared<EchoField>();
  SimulationOptions options = options_with(field);
  options.input_files.push_back(e_file);
  Simulation s(model, options);
  s.run();
  ASSERT_EQ(field->passes.size(), 1u);
  const env::Query& q = field->passes[0][0];
  EXPECT_EQ(q.turtle.position_count, 2);
  EXPECT_EQ(q.turtle.heading_count, 0);
  EXPECT_TRUE(q.following.symbol.empty());  // "following module:" defaults to no
}

// The answer of the pass before step 2 is what step 2's production reads,
// and no pass follows the last step.
TEST(EnvironmentPass, AnswersReachTheNextStep) {
  auto field = std::make_shared<StepField>();
  Simulation s(write_model("next-step", R"(#include <lpfgall.h>
module B(float);
derivation length: 2;
axiom: E1(0);
E1(v): { produce E1(v) B(v); }
)"),
               options_with(field));
  s.run();
  // The axiom E1(0) answered E1(0); step 1: E1(0) B(0), answered E1(10);
  // step 2: E1(10) B(10) B(0).
  EXPECT_EQ(string_of(s), "E1(10) B(10) B(0)");
  EXPECT_EQ(field->steps, (std::vector<int>{0, 1}));
}

// The switch is read when the pass is due, before StartEach: what step k's
// StartEach or EndEach sets decides the pass before step k + 1.
TEST(EnvironmentPass, NoEnvironmentSkipsTheNextPass) {
  // StepNo() is k in step k's StartEach and EndEach (lpfg -b, reference run).
  const char* switches[] = {
      "StartEach: { if (StepNo() == 2) NoEnvironment(); else Environment(); }",
      "EndEach: { if (StepNo() == 2) NoEnvironment(); else Environment(); }",
  };
  int n = 0;
  for (const char* control : switches) {
    auto field = std::make_shared<StepField>();
    Simulation s(write_model("no-environment-" + std::to_string(n++),
                             std::string("#include <lpfgall.h>\nderivation length: 4;\n") + control +
                                 "\naxiom: E1(0);\n"),
                 options_with(field));
    s.run();
    EXPECT_EQ(field->steps, (std::vector<int>{0, 1, 3})) << control;
    EXPECT_EQ(string_of(s), "E1(30)") << control;
  }
}

std::string write_cpfg(const std::string& name, const std::string& axiom) {
  return write_model(name, "Lsystem: 1\nderivation length: 1\nAxiom: " + axiom + "\nendlsystem\n");
}

// F(2) ends at (0,2,0); +(90) turns H to (-1,0,0); F(1) ends at (-1,2,0).
TEST(EnvironmentPass, CpfgCommunicationModulesOfAnyLength) {
  auto field = std::make_shared<EchoField>();
  Simulation s(write_cpfg("cpfg", "F(2)+(90)?E(0,0)F(1)?E(9)?E"), options_with(field));
  s.run();
  ASSERT_EQ(field->passes.size(), 1u);  // before the one step
  const std::vector<env::Query>& q = field->passes[0];
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q[0].module.symbol, "?E");
  EXPECT_EQ(q[0].module.parameters, (std::vector<float>{0, 0}));
  EXPECT_EQ(q[0].following.symbol, "F");
  EXPECT_EQ(q[0].following.parameters, std::vector<float>{1});
  EXPECT_EQ(q[1].following.symbol, "?E");
  EXPECT_TRUE(q[1].following.parameters.empty());
  EXPECT_TRUE(q[2].module.parameters.empty());
  EXPECT_TRUE(q[2].following.symbol.empty());  // the end of the string
  EXPECT_EQ(string_of(s), "F(2)+(90)?E(0,2)F(1)?E(-1)?E");
}

TEST(EnvironmentPass, ACpfgCommunicationModuleCarriesAtMostTwentyParameters) {
  std::string params = "0";
  for (int k = 1; k < 21; ++k) params += ",0";
  const std::string model = write_cpfg("too-many", "?E(" + params + ")");
  try {
    Simulation s(model, options_with(std::make_shared<EchoField>()));
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), model + ": error: a communication module ?E has 21 parameters; at most 20 can "
                                             "be exchanged with the environment");
  }
  // Without an environment the module is only a module.
  SimulationOptions plain;
  plain.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  EXPECT_NO_THROW(Simulation(model, plain));
}

// The following module's parameters as numbers: a struct's field names are
// labels, however many digits they hold, and NaN and infinity are values.
TEST(EnvironmentPass, FollowingStructParametersGiveTheirValuesOnly) {
  auto field = std::make_shared<EchoField>();
  Simulation s(write_model("following-struct", R"(#include <lpfgall.h>
#include <limits>
struct Pair { int x2; float y10; };
module S(Pair);
module N(float, double);
Pair pair() { Pair p; p.x2 = 7; p.y10 = 1.5f; return p; }
float not_a_number() { return std::numeric_limits<float>::quiet_NaN(); }
double minus_infinity() { return -std::numeric_limits<double>::infinity(); }
derivation length: 1;
axiom: E1(0) S(pair()) E1(0) N(not_a_number(), minus_infinity());
)"),
               options_with(field));
  s.run();
  ASSERT_EQ(field->passes.size(), 1u);
  const std::vector<env::Query>& q = field->passes[0];
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].following.symbol, "S");
  EXPECT_EQ(q[0].following.parameters, (std::vector<float>{7, 1.5f}));
  EXPECT_EQ(q[1].following.symbol, "N");
  ASSERT_EQ(q[1].following.parameters.size(), 2u);
  EXPECT_TRUE(std::isnan(q[1].following.parameters[0]));
  EXPECT_EQ(q[1].following.parameters[1], -std::numeric_limits<float>::infinity());
}

// Sets parameter `index` of every query.
class IndexField : public env::Field {
 public:
  explicit IndexField(int index) : index_(index) {}
  void answer(std::span<const env::Query>, std::span<env::Answer> answers, int) override {
    for (env::Answer& a : answers) a.assign(index_, 1);
  }

 private:
  int index_;
};

TEST(EnvironmentPass, AnAnswerForAMissingParameterIsAnError) {
  const std::string model =
      write_model("missing-parameter", "#include <lpfgall.h>\nderivation length: 1;\naxiom: F(1) E1(0);\n");
  try {
    Simulation s(model, options_with(std::make_shared<IndexField>(5)));
    s.run();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), model + ": error: the environment answered parameter 5 of module 1 (E1), "
                                             "which has 1 parameter, during the environmental pass before step 1");
  }
  // The last parameter it has is fine.
  Simulation s(write_model("last-parameter", "#include <lpfgall.h>\nderivation length: 1;\naxiom: E2(0,0);\n"),
               options_with(std::make_shared<IndexField>(1)));
  s.run();
  EXPECT_EQ(string_of(s), "E2(0,1)");
}

// As in lpfg and cpfg, a communication module that an interpretation rule
// replaces is not sent; the one the rule produces is sent, with the turtle
// where the rule puts it, and its answer goes nowhere (it is not in the
// string). F(2) ends at (0,2,0); the rule's F(1) brings its E1 to (0,3,0).
TEST(EnvironmentPass, InterpretationRulesDecideWhatIsSent) {
  auto field = std::make_shared<EchoField>();
  Simulation s(write_model("interpreted", R"(#include <lpfgall.h>
derivation length: 1;
axiom: F(2) E1(5) F(1) E2(1,2);
interpretation:
E1(v) : { produce F(1) E1(v); }
E2(a,b) : { produce; }
)"),
               options_with(field));
  s.run();
  ASSERT_EQ(field->passes.size(), 1u);
  const std::vector<env::Query>& q = field->passes[0];
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0].id, 1u);  // the place of the module the rule replaced
  EXPECT_EQ(q[0].module.symbol, "E1");
  EXPECT_EQ(q[0].module.parameters, std::vector<float>{5});
  expect_vector(q[0].turtle.position, {0, 3, 0});
  EXPECT_TRUE(q[0].following.symbol.empty());
  EXPECT_EQ(string_of(s), "F(2) E1(5) F(1) E2(1,2)");
}

}  // namespace
}  // namespace sylva::test
