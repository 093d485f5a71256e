// cpfg's labels (@L, CPFG manual 6.10), random functions bran and biran
// (5.3), twist control (@Tp @Tf, 6.8) and the back side's colour (@; @,,
// 6.3): small cpfg models worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "io/string_text.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/turtle_fixture.h"

namespace sylva::test::turtle_tests {
namespace {

struct CpfgModel {
  std::unique_ptr<Simulation> simulation;
  Scene scene;
  std::string trace;
};

// An L-system file of `body` (between Lsystem: and endlsystem), derived
// `steps` steps and drawn with the view file `view`.
CpfgModel cpfg_lsystem(const std::string& name, const std::string& body, int steps = 0,
                       const std::string& view = "angle increment: 90") {
  const std::string dir = make_temp_dir("cpfg-labels-" + name);
  std::ofstream(dir + "/lsystem.l") << "Lsystem: 1\nderivation length: " << steps << "\n" << body << "\nendlsystem\n";
  std::ofstream(dir + "/view.v") << view << "\n";
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  CpfgModel m;
  m.simulation = std::make_unique<Simulation>(dir + "/lsystem.l", SimulationOptions{build, {dir + "/view.v"}});
  m.simulation->run(steps);
  m.scene = m.simulation->scene();
  m.trace = m.simulation->turtle_trace(m.simulation->primary_view());
  return m;
}

std::string string_of(const CpfgModel& m) {
  return io::format_string(m.simulation->string(), m.simulation->types());
}

// The k-th parameter of the first module named `name` in the string.
float first_param(const CpfgModel& m, const std::string& name, int k) {
  const auto& types = m.simulation->types();
  for (abi::ModuleId id = 0; id < types.size(); ++id)
    if (types.name(id) == name && types[id].param_size >= 4u * static_cast<unsigned>(k + 1))
      return module_floats(*m.simulation, id, 0, k + 1)[static_cast<std::size_t>(k)];
  ADD_FAILURE() << "no module " << name;
  return NAN;
}

// ---- @L --------------------------------------------------------------------------

TEST(CpfgLabels, TextAndFormattedLabelsAtTheTurtlePosition) {
  CpfgModel m = cpfg_lsystem("labels", "Axiom: F@L(\"A\")F(2)@L(\"x=%g\", 2.5)");
  ASSERT_EQ(m.scene.labels.size(), 2u);
  EXPECT_EQ(m.scene.labels[0].text, "A");
  expect_near(m.scene.labels[0].position, {0, 1, 0});
  EXPECT_EQ(m.scene.labels[1].text, "x=2.5");
  expect_near(m.scene.labels[1].position, {0, 3, 0});
  EXPECT_EQ(m.scene.labels[0].color, 128);  // the turtle's colour
}

TEST(CpfgLabels, StringOutputWritesTheLabelAsWritten) {
  CpfgModel m = cpfg_lsystem("label-string",
                             "Axiom: A(3)\nA(n) --> @L(\"A\")@L(\"n=%g \\\"q\\\"\",n)@L(\"%d%%\",n*2)B(n)", 1);
  EXPECT_EQ(string_of(m), "@L(\"A\")@L(\"n=%g \\\"q\\\"\",3)@L(\"%d%%\",6)B(3)\n");
  ASSERT_EQ(m.scene.labels.size(), 3u);
  EXPECT_EQ(m.scene.labels[1].text, "n=3 \"q\"");
  EXPECT_EQ(m.scene.labels[2].text, "6%");
  EXPECT_NE(m.trace.find("@L(\"n=%g \"q\"\",3) \"n=3 \"q\"\""), std::string::npos) << m.trace;
}

TEST(CpfgLabels, FormatUsesOnlySafeConversions) {
  const float v[] = {2.5f, -7.9f, 1e30f};
  EXPECT_EQ(turtle::format_cpfg_label("plain", v, 0), "plain");
  EXPECT_EQ(turtle::format_cpfg_label("%g|%5.2f|%e", v, 3), "2.5|-7.90|1.000000e+30");
  EXPECT_EQ(turtle::format_cpfg_label("%d %i %x", v, 2), "2 -7 %x");  // no third value: as written
  EXPECT_EQ(turtle::format_cpfg_label("%ld %lf", v, 2), "2 -7.900000");
  // %s %n %p %* and huge widths would read what is not there: written as they stand.
  EXPECT_EQ(turtle::format_cpfg_label("%s%n%p%*d", v, 3), "%s%n%p%*d");
  EXPECT_EQ(turtle::format_cpfg_label("%99999g|%g", v, 1), "%99999g|2.5");
  EXPECT_EQ(turtle::format_cpfg_label("%d", v + 2, 1), "%d");  // 1e30 is no integer
  EXPECT_EQ(turtle::format_cpfg_label("100%% %", v, 1), "100% %");
  EXPECT_EQ(turtle::format_cpfg_label("[%-6.1f]", v, 1), "[2.5   ]");
}

TEST(CpfgLabels, LabelErrors) {
  for (const auto& [body, message] : std::vector<std::pair<std::string, std::string>>{
           {"Axiom: @L(1)", "@L takes a string first"},
           {"Axiom: F(\"x\")", "supported only as the first of @L"},
           {"Axiom: @L(1,\"x\")", "supported only as the first of @L"},
           {"Axiom: A\n@L(x) --> F", "@L(...) in a predecessor is not supported yet"},
       }) {
    try {
      cpfg_lsystem("label-error", body);
      ADD_FAILURE() << body << ": no error";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << body << ": " << e.what();
    }
  }
}

// ---- bran, biran --------------------------------------------------------------

TEST(CpfgRandom, BranAndBiranHaveTheirMeans) {
  // Start: averages of 20000 draws each, after srand; the production copies them out.
  CpfgModel m = cpfg_lsystem("bran-biran",
                             "Start: { srand(7); i = 0; b = 0; b2 = 0; c = 0; h = 0; lo = 1; hi = 0; bad = 0;\n"
                             " while (i < 20000) { x = bran(2, 3); b = b + x; b2 = b2 + x * x;\n"
                             "   h = h + bran(0.5, 0.5); y = biran(10, 0.3); c = c + y;\n"
                             "   if (x < lo) { lo = x; } if (x > hi) { hi = x; }\n"
                             "   if (y != floor(y) || y < 0 || y > 10) { bad = bad + 1; } i = i + 1; } }\n"
                             "Axiom: A\nA --> M(b / i, b2 / i, h / i, c / i, lo, hi, bad)",
                             1);
  // Beta(2,3): mean 2/5, E[x^2] = var + mean^2 = 1/25 + 4/25; standard errors ~0.0014.
  EXPECT_NEAR(first_param(m, "M", 0), 0.4, 0.01);
  EXPECT_NEAR(first_param(m, "M", 1), 0.2, 0.01);
  // Beta(0.5,0.5) (a < 1: the boosted gamma variates): mean 1/2.
  EXPECT_NEAR(first_param(m, "M", 2), 0.5, 0.015);
  // Binomial(10,0.3): mean 3 (standard error ~0.01), whole numbers in 0..10.
  EXPECT_NEAR(first_param(m, "M", 3), 3.0, 0.06);
  EXPECT_GE(first_param(m, "M", 4), 0.0f);
  EXPECT_LE(first_param(m, "M", 5), 1.0f);
  EXPECT_EQ(first_param(m, "M", 6), 0.0f);
}

TEST(CpfgRandom, BranIsSeededBySrandLikeRan) {
  const std::string body = "Start: { srand(3); a = bran(2, 2); srand(3); b = bran(2, 2); c = biran(5, 0.5); "
                           "srand(3); d = ran(1); e = ran(1); }\nAxiom: A\nA --> M(a, b, c, d, e)";
  CpfgModel m = cpfg_lsystem("bran-seed", body, 1);
  EXPECT_EQ(first_param(m, "M", 0), first_param(m, "M", 1));
  // bran draws from ran's generator: the same seed gives another first value than ran's.
  EXPECT_NE(first_param(m, "M", 0), first_param(m, "M", 3));
}

// ---- @Tp, @Tf -----------------------------------------------------------------

// The positions and up vectors below are the reference cpfg's (?P and ?U
// after each F; a segment's up is the frame's, cpfg's U negated).
TEST(CpfgTwist, MinimizeTwistUndoesTheRollSinceTheLastStep) {
  // /(90)&(90) turns H to +x with U (cpfg's) at -y; @Tp carries the last F's
  // U (-z) round with the heading instead: cpfg ?U(0,0,-1), and + heads along +y.
  CpfgModel with = cpfg_lsystem("twist-tp", "Axiom: F/(90)&(90)@Tp F+(90)F");
  ASSERT_EQ(with.scene.segments.size(), 3u);
  expect_near(with.scene.segments[1].end, {1, 1, 0});
  expect_near(with.scene.segments[1].up, {0, 0, 1});
  expect_near(with.scene.segments[2].end, {1, 2, 0});
  CpfgModel without = cpfg_lsystem("twist-no-tp", "Axiom: F/(90)&(90)F+(90)F");
  ASSERT_EQ(without.scene.segments.size(), 3u);
  expect_near(without.scene.segments[1].up, {0, 1, 0});
  expect_near(without.scene.segments[2].end, {1, 1, -1});
}

TEST(CpfgTwist, MinimizeTwistKeepsAPureRollAndForceTwistKeepsTheTwist) {
  // A roll with no turn of the heading since the last F: @Tp leaves it (?P(-0.866025,1,-0.5)).
  CpfgModel roll = cpfg_lsystem("twist-roll", "Axiom: F/(30)@Tp+(90)F");
  ASSERT_EQ(roll.scene.segments.size(), 2u);
  expect_near(roll.scene.segments[1].end, {-0.866025f, 1, -0.5f});
  CpfgModel pitch = cpfg_lsystem("twist-pitch", "Axiom: F&(90)@Tp F");
  ASSERT_EQ(pitch.scene.segments.size(), 2u);
  expect_near(pitch.scene.segments[1].end, {0, 1, -1});
  expect_near(pitch.scene.segments[1].up, {0, 1, 0});
  CpfgModel force = cpfg_lsystem("twist-force", "Axiom: F/(90)@Tf+(90)F");
  ASSERT_EQ(force.scene.segments.size(), 2u);
  expect_near(force.scene.segments[1].end, {0, 1, -1});
  // @Tf makes the roll the twist @Tp keeps: cpfg gives the same ?P with @Tf@Tp.
  CpfgModel kept = cpfg_lsystem("twist-force-kept", "Axiom: F/(90)&(90)@Tf@Tp F");
  ASSERT_EQ(kept.scene.segments.size(), 2u);
  expect_near(kept.scene.segments[1].end, {1, 1, 0});
  expect_near(kept.scene.segments[1].up, {0, 1, 0});
}

// ---- @; @, ------------------------------------------------------------------------

TEST(CpfgBackColor, BackColourStepsAndSetsWithoutChangingTheFront) {
  CpfgModel m = cpfg_lsystem("back-color", "Axiom: F@;F@;(40)F@,F", 0,
                             "angle increment: 90\ninitial color: 5\ncolor increment: 2 3");
  ASSERT_EQ(m.scene.segments.size(), 4u);
  for (const auto& s : m.scene.segments) EXPECT_EQ(s.color, 5);
  // From the front's 5 by the second increment 3, then set to 40, then down by 3.
  EXPECT_NE(m.trace.find("@; back colour 8"), std::string::npos) << m.trace;
  EXPECT_NE(m.trace.find("@;(40) back colour 40"), std::string::npos) << m.trace;
  EXPECT_NE(m.trace.find("@, back colour 37"), std::string::npos) << m.trace;
}

}  // namespace
}  // namespace sylva::test::turtle_tests
