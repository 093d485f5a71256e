// The function files lpfg and cpfg read (VLAB Tools manual 8.4, 10.3):
// points with a multiplicity, the timeline editor's .tset files, cpfg's
// samples for the older format, and the one list of functions lpfg makes of
// .fset, .tset, .vset and .func files. Files written by hand after the
// manual and the editors' own files; values checked by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "inputs/function_file.h"
#include "inputs/input_files.h"
#include "inputs/input_test_helpers.h"

namespace sylva {
namespace {

using test::error_of;
using test::write_file;

// funcedit writes a third number after x and y: the point's multiplicity.
TEST(FunctionFiles, APointsMultiplicityRepeatsIt) {
  const std::string dir = test::make_temp_dir("function-multiplicity");
  geometry::Function f = io::read_function_file(
      write_file(dir, "m.func", "fver 1 1\nname: m\nsamples: 10\nflip: off\npoints: 4\n"
                                "0 0 1\n0.5 1 2\n0.7 0.5 0\n1 0 1\n"));
  ASSERT_EQ(f.points.size(), 4u);  // 1 + 2 + 0 + 1
  EXPECT_EQ(f.points[1], (geometry::Vec2{0.5f, 1}));
  EXPECT_EQ(f.points[2], (geometry::Vec2{0.5f, 1}));
  EXPECT_EQ(f.points[3], (geometry::Vec2{1, 0}));
}

// The timeline editor's file (its own example's layout): the embedded
// function's name, the timeline's interval; colour and labels read past,
// labels possibly empty.
const char* const kTimelines =
    "timeEdit 1 2\nitems: 2\n"
    "start: 2\nend: 15.08\nname: INT_WIDTH\nstartLabel: \nendLabel: \ntimelineFunceditFileStart:\n"
    "fver 1 1\nname: width\nsamples: 20\nflip: off\npoints: 4\n0 0\n0.3 0\n0.6 0\n1 0\n"
    "timelineFunceditFileEnd:\n"
    "start: -20.5\nend: 1\nname: AGE\ncolor: 102,102,153\nstartLabel: T1\nendLabel: T3\ntimelineFunceditFileStart:\n"
    "fver 1 1\nsamples: 20\nflip: off\npoints: 4\n0 0\n0.3 0.3\n0.6 0.6\n1 1\n"
    "timelineFunceditFileEnd:\n";

TEST(FunctionFiles, TimelinesGiveTheirIntervalAndTheirFunctionsName) {
  const std::string dir = test::make_temp_dir("timelines");
  std::vector<geometry::Function> t = io::read_timeline_set_file(write_file(dir, "t.tset", kTimelines));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "width");
  EXPECT_FLOAT_EQ(t[0].low, 2);
  EXPECT_FLOAT_EQ(t[0].up, 15.08f);
  EXPECT_EQ(t[0].samples, 20);
  EXPECT_EQ(t[1].name, "AGE");  // no name of its own: the timeline's
  EXPECT_FLOAT_EQ(t[1].low, -20.5f);
  EXPECT_EQ(t[1].points[2], (geometry::Vec2{0.6f, 0.6f}));
}

// A timeline without a function does not load in lpfg either.
TEST(FunctionFiles, ATimelineWithoutAFunctionIsAnError) {
  const std::string dir = test::make_temp_dir("timeline-empty");
  const std::string path = write_file(dir, "e.tset",
                                      "timeEdit 1 2\nitems: 1\nstart: 0\nend: 1\nname: X\nstartLabel: \nendLabel: \n"
                                      "timelineFunceditFileStart:\ntimelineFunceditFileEnd:\n");
  EXPECT_EQ(error_of([&] { io::read_timeline_set_file(path); }),
            path + ":9:1: error: expected the timeline's function ('fver'), found 'timelineFunceditFileEnd:'");
}

// cpfg tabulates a "range:" file at the view file's count, an "fver" file
// at its own.
TEST(FunctionFiles, CpfgsSamplesForEachFormat) {
  const std::string dir = test::make_temp_dir("cpfg-samples");
  const std::string old = write_file(dir, "o.func", "range: 0.0 1.0\npoints: 4\n0 1\n0.25 0.8\n0.75 0.2\n1 0\n");
  const std::string fver =
      write_file(dir, "f.func", "fver 1 1\nname: f\nsamples: 7\nflip: off\npoints: 4\n0 1\n0.25 0.8\n0.75 0.2\n1 0\n");
  EXPECT_EQ(io::read_cpfg_function_file(old, 20).samples, 20);
  EXPECT_EQ(io::read_cpfg_function_file(old).samples, -1);
  EXPECT_EQ(io::read_cpfg_function_file(fver, 20).samples, 7);
  // In a set, cpfg reads a "range:" function with 100 samples.
  const std::string set = write_file(dir, "s.fset",
                                     "funcgalleryver 1 1\nitems: 2\n"
                                     "fver 1 1\nname: f\nsamples: 7\nflip: off\npoints: 4\n0 1\n0.25 0.8\n0.75 0.2\n1 0\n"
                                     "range: 0.0 1.0\npoints: 4\n0 1\n0.25 0.8\n0.75 0.2\n1 0\n");
  const std::vector<geometry::Function> functions = io::read_cpfg_function_set_file(set);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].samples, 7);
  EXPECT_EQ(functions[1].samples, 100);
}

// lpfg's list: the last .fset's functions, the .tset's, the .vset's
// parameters, then the .func files' in command-line order; a second .fset
// replaces the first, with a warning.
TEST(FunctionFiles, LpfgNumbersFunctionsOfAllFilesInOneList) {
  const std::string dir = test::make_temp_dir("function-list");
  auto func = [](const std::string& name) {
    return "fver 1 1\nname: " + name + "\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.3 0.3\n0.6 0.6\n1 1\n";
  };
  const std::string a = write_file(dir, "a.func", func("alpha"));
  const std::string unused = write_file(dir, "x.fset", "funcgalleryver 1 1\nitems: 1\n" + func("unused"));
  const std::string set = write_file(dir, "s.fset", "funcgalleryver 1 1\nitems: 1\n" + func("gamma"));
  const std::string panel = write_file(dir, "p.vset", "#define SIZE 3\n");
  const std::string timelines = write_file(dir, "t.tset", kTimelines);
  const std::string b = write_file(dir, "b.func", func("beta"));
  io::InputFiles in = io::read_input_files({a, unused, panel, set, b, timelines});
  std::vector<std::string> names;
  for (const geometry::Function& f : in.functions) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gamma", "width", "AGE", "SIZE", "alpha", "beta"}));
  EXPECT_EQ(in.functions[3].constant, 3.0f);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_NE(in.warnings[0].find("s.fset: warning: a second function set file; it replaces"), std::string::npos)
      << in.warnings[0];
}

}  // namespace
}  // namespace sylva
