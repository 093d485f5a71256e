// The communication specification file (.e, EnviroManual section 2): what
// each command sets, how many values a turtle format sends, the warnings for
// what lpfg and cpfg pass over and the errors where they could not go on,
// which point at the file, line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "env/comm_spec.h"
#include "env/turtle_format.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::env {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_comm_spec(text, "plant.e");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CommSpec, ReadsEveryCommand) {
  const CommSpec spec = parse_comm_spec(
      "executable: honda81 -e honda.e honda.par\n"
      "communication type: pipes\n"
      "turtle position: P:%.3f %.3f\n"
      "turtle heading: H:%g %g %g\n"
      "turtle left: %f\n"
      "turtle up: %e %e\n"
      "turtle line width: %g\n"
      "turtle scale factor: %5.2f\n"
      "following module: yes\n"
      "interpreted modules: L1 L2, L3\n"
      "verbose: on\n",
      "plant.e");
  EXPECT_EQ(spec.executable, "honda81 -e honda.e honda.par");
  EXPECT_EQ(spec.executable_line, 1);
  EXPECT_EQ(spec.executable_column, 13);
  EXPECT_EQ(spec.communication_type, "pipes");
  EXPECT_EQ(spec.position.text, "P:%.3f %.3f");
  EXPECT_EQ(spec.position.count, 2);
  EXPECT_EQ(spec.heading.count, 3);
  EXPECT_EQ(spec.left.count, 1);
  EXPECT_EQ(spec.up.count, 2);
  EXPECT_EQ(spec.line_width.count, 1);
  EXPECT_EQ(spec.scale_factor.count, 1);
  EXPECT_TRUE(spec.following_module);
  EXPECT_EQ(spec.interpreted_modules, (std::vector<std::string>{"L1", "L2", "L3"}));
  EXPECT_TRUE(spec.verbose);
}

TEST(CommSpec, DefaultsSendNoTurtleAndNoFollowingModule) {
  const CommSpec spec = parse_comm_spec("  Executable :  ./env   \r\ncommunication   type: Files\n\n", "plant.e");
  EXPECT_EQ(spec.executable, "./env");
  EXPECT_EQ(spec.communication_type, "files");
  EXPECT_EQ(spec.position.count, 0);
  EXPECT_EQ(spec.line_width.count, 0);
  EXPECT_FALSE(spec.following_module);
  EXPECT_FALSE(spec.verbose);
  EXPECT_TRUE(spec.interpreted_modules.empty());
}

TEST(CommSpec, ReadsAFile) {
  const std::string path = test::make_temp_dir("comm-spec") + "/plant.e";
  std::ofstream(path) << "executable: chiba chiba.par\ncommunication type: memory\nturtle position: %g %g %g\n";
  const CommSpec spec = read_comm_spec(path);
  EXPECT_EQ(spec.path, path);
  EXPECT_EQ(spec.position.count, 3);
}

// Where lpfg or cpfg would print a format's text for numbers it cannot take,
// the run stops.
TEST(CommSpec, UnusableFilesPointAtTheFault) {
  // The fourth conversion of "%g %g %g %g" starts at column 27.
  EXPECT_EQ(error_of("executable: a\ncommunication type: pipes\nturtle position: %g %g %g %g\n"),
            "plant.e:3:27: error: at most 3 values can be sent for this field");
  EXPECT_EQ(error_of("executable: a\ncommunication type: pipes\nturtle line width: %g %g\n"),
            "plant.e:3:23: error: at most 1 value can be sent for this field");
  EXPECT_EQ(error_of("executable: a\ncommunication type: pipes\nturtle heading: %s\n"),
            "plant.e:3:17: error: expected a number conversion such as %g, %f or %.3f");
  EXPECT_EQ(error_of("executable: a\ncommunication type: pipes\nturtle up: none\n"),
            "plant.e:3:12: error: expected a format with at least one conversion, such as %g");
}

// lpfg ("Environment command line not specified") and the communication
// library ("Environment ignored") run without the environment when the file
// names no program: a warning, and no executable.
TEST(CommSpec, WithoutAProgramTheEnvironmentIsIgnored) {
  const CommSpec empty = parse_comm_spec("executable:\ncommunication type: pipes\n", "plant.e");
  EXPECT_TRUE(empty.executable.empty());
  ASSERT_EQ(empty.warnings.size(), 2u);
  EXPECT_EQ(empty.warnings[0].rfind("plant.e:1:12: warning: expected the command line of the environmental program", 0), 0u)
      << empty.warnings[0];
  const CommSpec none = parse_comm_spec("communication type: pipes\n", "plant.e");
  EXPECT_TRUE(none.executable.empty());
  ASSERT_EQ(none.warnings.size(), 1u);
  EXPECT_NE(none.warnings[0].find("plant.e:1: warning: no 'executable:' names the environmental program; the "
                                  "environment is ignored"),
            std::string::npos)
      << none.warnings[0];
}

// What lpfg and cpfg pass over (lpfg's "Unrecognized command", the
// communication library's "unknown directive", a value overwritten by a
// later line) is a warning, and the run goes on.
TEST(CommSpec, WhatTheReferenceProgramsPassOverIsAWarning) {
  const CommSpec spec = parse_comm_spec(
      "executable: a\n"
      "turtle position %g\n"
      "  turtle colour: %g\n"
      "communication type: carrier pigeon\n"
      "following module: perhaps\n"
      "executable: b -e plant.e b.spec\n"
      "verbose: on\n",
      "plant.e");
  EXPECT_EQ(spec.executable, "b -e plant.e b.spec");  // the later line wins
  EXPECT_EQ(spec.executable_line, 6);
  EXPECT_FALSE(spec.following_module);
  EXPECT_TRUE(spec.verbose);
  EXPECT_EQ(spec.position.count, 0);
  ASSERT_EQ(spec.warnings.size(), 5u);
  EXPECT_EQ(spec.warnings[0], "plant.e:2:1: warning: not a 'command: value' line; ignored, as lpfg and cpfg ignore it");
  EXPECT_EQ(spec.warnings[1].rfind("plant.e:3:3: warning: unknown command 'turtle colour' ignored", 0), 0u)
      << spec.warnings[1];
  EXPECT_EQ(spec.warnings[2],
            "plant.e:4:21: warning: unknown communication type 'carrier pigeon'; the communication library uses pipes");
  EXPECT_EQ(spec.warnings[3], "plant.e:5:19: warning: expected yes or no (on or off), not 'perhaps'; left as it was");
  EXPECT_EQ(spec.warnings[4], "plant.e:6:1: warning: 'executable:' is given again; this one replaces the first");
  // No communication type at all is fine: lpfg does not read it.
  EXPECT_TRUE(parse_comm_spec("executable: a\n", "plant.e").warnings.empty());
}

TEST(CommSpec, AMissingFileIsNamed) {
  try {
    read_comm_spec("/nonexistent/plant.e");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/plant.e: error: cannot open the communication specification file");
  }
}

TEST(TurtleFormat, FormatsValuesAsPrintfWould) {
  TurtleFormat f;
  std::string error;
  std::size_t column = 0;
  ASSERT_TRUE(parse_turtle_format("P:%.3f %g 100%% %d", 3, f, error, column));
  EXPECT_EQ(f.count, 3);
  const float values[3] = {1.5f, -0.25f, 7.9f};
  EXPECT_EQ(format_turtle_values(f, values), "P:1.500 -0.25 100% 7");
}

TEST(TurtleFormat, AnIntegerPastTheRangeOfLongLongIsItsNearestEnd) {
  TurtleFormat f;
  std::string error;
  std::size_t column = 0;
  ASSERT_TRUE(parse_turtle_format("%d %i %d", 3, f, error, column));
  const float values[3] = {-2e30f, 2e30f, INFINITY};
  EXPECT_EQ(format_turtle_values(f, values), "-9223372036854775808 9223372036854775807 0");
}

}  // namespace
}  // namespace sylva::env
