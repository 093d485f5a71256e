// The studio's parameters: which panel edits which file, where a slider
// starts, and what moving it writes.
#include "studio/parameters.h"

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::studio {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const char* kModel = "#define WIDTH 4\n#define LEAVES 1\nderivation length: 3;\n";
// A vlab panel of the manual's form (VLAB Tools manual 2.4).
const char* kPanel =
    "panel name: L-system\nbackground: 512\nsize: 170 80\n\n"
    "type: SLIDER\nname: Eccentricity\ncolors: 518 519\norigin: 20 20\nmin/max: 1 100\nvalue: 40\n"
    "message: d WIDTH %d 10\n\n"
    "type: BUTTON\nname: Leaves\ntricolor: 1 2 3\norigin: 5 5\nvalue: 1\nmessage: d LEAVES %d\n";

TEST(StudioParameters, ASpecificationsFileSaysWhichFileAPanelEdits) {
  const std::string dir = test::make_temp_dir("params-spec");
  write(dir + "/plant.l", kModel);
  write(dir + "/panel.l", kPanel);
  write(dir + "/specifications", "L-system:\n\tpanel:\n\t\tpanel panel.l | awkped plant.l\n\tEDIT plant.l\n");
  std::vector<std::string> problems;
  const std::vector<Parameter> params = find_parameters(dir, dir + "/plant.l", {}, problems);
  ASSERT_EQ(params.size(), 2u);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(params[0].name, "Eccentricity");
  EXPECT_EQ(params[0].define, "WIDTH");
  EXPECT_EQ(params[0].target, dir + "/plant.l");
  EXPECT_EQ(params[0].scale, 10);
  // The file says 4 = 40 / 10: the slider starts there.
  EXPECT_EQ(params[0].value, 40);
  EXPECT_FALSE(params[0].modified());
  EXPECT_EQ(params[1].kind, Parameter::Kind::Button);
  EXPECT_EQ(params[1].value, 1);
}

TEST(StudioParameters, ASliderStartsWhereTheFileIsNotWhereThePanelSays) {
  const std::string dir = test::make_temp_dir("params-file-value");
  write(dir + "/plant.l", "#define WIDTH 2.5\n");
  write(dir + "/panel.l", kPanel);
  std::vector<std::string> problems;
  const std::vector<Parameter> params = find_parameters(dir, dir + "/plant.l", {}, problems);
  ASSERT_FALSE(params.empty());
  EXPECT_EQ(params[0].value, 25);
}

TEST(StudioParameters, WithoutSpecificationsAPanelEditsTheFileOfItsKind) {
  const std::string dir = test::make_temp_dir("params-kind");
  write(dir + "/plant.l", kModel);
  write(dir + "/plant.a", "swap interval: 10\n");
  write(dir + "/panel.a",
        "panel name: Animation\n\ntype: SLIDER\nname: Swap\nmin/max: 0 50\nvalue: 10\nmessage: n 1 1 0 %d\n");
  std::vector<std::string> problems;
  const std::vector<Parameter> params =
      find_parameters(dir, dir + "/plant.l", {io::InputFile(dir + "/plant.a")}, problems);
  ASSERT_EQ(params.size(), 1u);
  EXPECT_EQ(params[0].target, dir + "/plant.a");
  Parameter moved = params[0];
  moved.value = 25;
  EXPECT_EQ(apply_parameter("swap interval: 10\n", moved), "swap interval: 25\n");
}

TEST(StudioParameters, MovingASliderWritesValueOverScale) {
  const std::string dir = test::make_temp_dir("params-apply");
  write(dir + "/plant.l", kModel);
  write(dir + "/panel.l", kPanel);
  std::vector<std::string> problems;
  std::vector<Parameter> params = find_parameters(dir, dir + "/plant.l", {}, problems);
  ASSERT_FALSE(params.empty());
  params[0].value = 46;  // the manual's example: d SIZE 46 10 sets 4.6
  EXPECT_EQ(apply_parameter(kModel, params[0]), "#define WIDTH 4.6\n#define LEAVES 1\nderivation length: 3;\n");
}

TEST(StudioParameters, WithoutAPanelTheModelsNumericDefinesAreSliders) {
  const std::string dir = test::make_temp_dir("params-defines");
  write(dir + "/plant.l", "#define ANGLE 30\n#define RATE 0.5\n#define NAME \"x\"\n");
  std::vector<std::string> problems;
  std::vector<Parameter> params = find_parameters(dir, dir + "/plant.l", {}, problems);
  ASSERT_EQ(params.size(), 2u);
  EXPECT_EQ(params[0].define, "ANGLE");
  EXPECT_EQ(params[0].value, 30);  // integers move by 1
  EXPECT_EQ(params[0].scale, 1);
  params[0].value = 45;
  EXPECT_EQ(apply_parameter("#define ANGLE 30\n", params[0]), "#define ANGLE 45\n");
  // 0.5 moves in its third significant digit, 0.001: 500 positions = 0.5.
  EXPECT_EQ(params[1].define, "RATE");
  EXPECT_EQ(params[1].value, 500);
  params[1].value = 750;
  EXPECT_EQ(apply_parameter("#define RATE 0.5\n", params[1]), "#define RATE 0.75\n");
}

TEST(StudioParameters, AnUnreadablePanelIsAProblemNotAFailure) {
  const std::string dir = test::make_temp_dir("params-bad-panel");
  write(dir + "/plant.l", "#define ANGLE 30\n");
  write(dir + "/panel.l", "panel name: P\n\ntype: SLIDER\nname: S\nmin/max: one ten\nmessage: d ANGLE %d\n");
  std::vector<std::string> problems;
  const std::vector<Parameter> params = find_parameters(dir, dir + "/plant.l", {}, problems);
  EXPECT_EQ(problems.size(), 1u);
  // Without a panel that reads, the defines are offered.
  ASSERT_EQ(params.size(), 1u);
  EXPECT_EQ(params[0].define, "ANGLE");
}

}  // namespace
}  // namespace sylva::studio
