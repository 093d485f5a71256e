// func, tfunc, pfunc, funcTangent and val in an L+C model give lpfg's values
// to the last bit: the expected output is what the reference lpfg printed
// for this model and these files (lpfg -b lsystem.l shapes.fset growth.tset
// panel.vset taper.func, Virtual Laboratory 5.1).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// Two functions, the second with a doubled point ("0.5 1 2") and fewer
// samples than lpfg keeps (5: lpfg takes 10).
const char* const kShapes =
    "funcgalleryver 1 1\nitems: 2\n"
    "fver 1 1\nname: rise\nsamples: 20\nflip: off\npoints: 4\n"
    "0.000000 0.100000\n0.300000 0.900000\n0.700000 0.200000\n1.000000 1.000000\n"
    "fver 1 1\nname: bump\nsamples: 5\nflip: off\npoints: 5\n"
    "0.000000 0.000000 1\n0.250000 0.000000 1\n0.500000 1.000000 2\n0.750000 0.000000 1\n1.000000 0.000000 1\n";
// A timeline from 2 to 12, as the timeline editor writes it.
const char* const kGrowth =
    "timeEdit 1 2\nitems: 1\nstart: 2\nend: 12\nname: GROWTH\ncolor: 102,102,153\nstartLabel: \nendLabel: T2\n"
    "timelineFunceditFileStart:\n"
    "fver 1 1\nname: growth\nsamples: 50\nflip: off\npoints: 4\n"
    "0.000000 0.000000\n0.400000 0.100000\n0.600000 0.900000\n1.000000 1.000000\n"
    "timelineFunceditFileEnd:\n";
const char* const kPanel = "#define LENGTH 2.5\n#define ANGLE 60\n";
// More samples than lpfg keeps (1500: lpfg takes 1000).
const char* const kTaper =
    "fver 1 1\nname: taper\nsamples: 1500\nflip: off\npoints: 4\n"
    "0.000000 1.000000\n0.250000 0.800000\n0.750000 0.200000\n1.000000 0.000000\n";

const char* const kModel = R"(#include <lpfgall.h>
derivation length: 1;
module A();
Axiom: A;
Start: {
  Printf("ids %d %d %d %d %d %d\n", rise, bump, growth, LENGTH, ANGLE, taper);
  Printf("func %.9g %.9g %.9g %.9g %.9g\n", func(rise, 0), func(rise, 0.37f), func(rise, 1), func(rise, -1), func(rise, 2));
  Printf("bump %.9g %.9g %.9g\n", func(bump, 0.5f), func(bump, 0.3f), func(bump, 0.61f));
  Printf("taper %.9g %.9g\n", func(taper, 0.1f), func(taper, 0.55f));
  Printf("tfunc %.9g %.9g %.9g %.9g\n", tfunc(growth, 2), tfunc(growth, 7.3f), tfunc(growth, 12), tfunc(growth, 20));
  Printf("funcg %.9g\n", func(growth, 0.53f));
  V2f t = funcTangent(rise, 0.37f);
  Printf("tangent %.9g %.9g\n", t.x, t.y);
  Printf("val %g %g\n", val(LENGTH), val(ANGLE));
  Printf("pfunc %.9g %.9g\n", pfunc(rise, 3, 1, 5), tfunc(rise, 3.5f));
  V2f t2 = funcTangent(rise, 3.5f);
  Printf("tangent2 %.9g %.9g\n", t2.x, t2.y);
}
)";

TEST(FunctionValues, FuncTfuncPfuncFuncTangentAndValAsLpfgComputesThem) {
  const std::string dir = make_temp_dir("function-values");
  std::ofstream(dir + "/lsystem.l") << kModel;
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  for (auto [file, text] : {std::pair{"shapes.fset", kShapes}, {"growth.tset", kGrowth}, {"panel.vset", kPanel},
                            {"taper.func", kTaper}}) {
    std::ofstream(dir + "/" + file) << text;
    options.input_files.push_back(dir + "/" + file);
  }
  // Printf's output; the input files' warnings are checked below.
  std::string messages;
  Simulation s(dir + "/lsystem.l", options, [&](const std::string& m) {
    if (m.find(": warning: ") == std::string::npos) messages += m;
  });
  s.run();
  // lpfg numbers the .fset's functions, the .tset's, the .vset's parameters,
  // then the .func files'. func(f, 0) is not quite the first point's y: lpfg
  // tabulates y where bisection finds x within 0.01/samples. tfunc maps
  // [2,12] onto [0,1]; pfunc(rise, 3, 1, 5) makes [1,5] rise's interval for
  // good, so tfunc and funcTangent use it afterwards.
  EXPECT_EQ(messages,
            "ids 1 2 3 4 5 6\n"
            "func 0.101170801 0.525475919 0.998829186 0.101170801 0.998829186\n"
            "bump 0.780841827 0.322393954 0.590855241\n"
            "taper 0.912043989 0.446685135\n"
            "tfunc 3.66523818e-05 0.545158923 0.999963284 0.999963284\n"
            "funcg 0.545158803\n"
            "tangent 1.04066181 0.29007256\n"
            "val 2.5 60\n"
            "pfunc 0.549999952 0.998829186\n"
            "tangent2 1.04124415 0.281338155\n");
  // lpfg says it keeps 10 to 1000 samples; so does Sylva, naming the function.
  bool bump = false, taper = false;
  for (const std::string& w : s.inputs().warnings) {
    bump |= w.find("bump") != std::string::npos && w.find("lpfg keeps 10") != std::string::npos;
    taper |= w.find("taper") != std::string::npos && w.find("lpfg keeps 1000") != std::string::npos;
  }
  EXPECT_TRUE(bump && taper);
}

}  // namespace
}  // namespace sylva::test
