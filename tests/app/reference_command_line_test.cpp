// lpfg's and cpfg's command lines, read from strings: which file is the
// model, what every other file is, and what becomes of the reference
// programs' options. Expected roles follow lpfg's comlineparam.cpp (files by
// extension, in any order) and cpfg's control.c (-m/-M/-e name the next
// file; then the L-system, view and animation files by place).
#include <gtest/gtest.h>

#include <stdexcept>

#include "api/reference_command_line.h"

namespace sylva {
namespace {

// Sylva's own options as the command line has them: -o and --string take a
// value, --verbose none.
std::optional<int> sylva_options(const std::string& name) {
  if (name == "-o" || name == "--string" || name == "-s" || name == "--steps" || name == "-n") return 1;
  if (name == "--verbose" || name == "-v") return 0;
  return std::nullopt;
}

ReferenceCommandLine read(const std::vector<std::string>& arguments) {
  return read_reference_command_line(arguments, sylva_options);
}

struct Role {
  std::string path;
  io::InputKind kind;
  int slot;
  bool operator==(const Role&) const = default;
};

std::vector<Role> roles(const ReferenceCommandLine& line) {
  std::vector<Role> out;
  for (const io::InputFile& f : line.inputs) out.push_back({f.path, f.kind, f.slot});
  return out;
}

TEST(ReferenceCommandLine, LpfgTakesFilesInAnyOrderByExtension) {
  ReferenceCommandLine line = read({"color.map", "lsystem.l", "view.v", "anim.a", "commfile.e", "f.fset"});
  EXPECT_EQ(line.model, "lsystem.l");
  EXPECT_EQ(roles(line), (std::vector<Role>{{"color.map", io::InputKind::Colormap, 1},
                                           {"view.v", io::InputKind::View, 1},
                                           {"anim.a", io::InputKind::Animation, 1},
                                           {"commfile.e", io::InputKind::Environment, 1},
                                           {"f.fset", io::InputKind::FunctionSet, 1}}));
  EXPECT_TRUE(line.notes.empty());
  EXPECT_TRUE(line.sylva_arguments.empty());
}

TEST(ReferenceCommandLine, CpfgFlagsNameTheFileAfterThem) {
  ReferenceCommandLine line = read({"-m1", "sedge.map", "-m2", "sedge.map2", "-M", "p.mat", "-e", "env.e", "sedge.l",
                                    "sedge.v", "sedge.a"});
  EXPECT_EQ(line.model, "sedge.l");
  EXPECT_EQ(roles(line), (std::vector<Role>{{"sedge.map", io::InputKind::Colormap, 1},
                                           {"sedge.map2", io::InputKind::Colormap, 2},
                                           {"p.mat", io::InputKind::Materials, 1},
                                           {"env.e", io::InputKind::Environment, 1},
                                           {"sedge.v", io::InputKind::View, 1},
                                           {"sedge.a", io::InputKind::Animation, 1}}));
}

// cpfg reads the second and third files as the view and animation files
// whatever their names; lpfg would not know them.
TEST(ReferenceCommandLine, CpfgReadsViewAndAnimationFilesByPlace) {
  ReferenceCommandLine line = read({"-m", "c.map", "plant.lsys", "plant.view", "plant.anim"});
  EXPECT_EQ(line.model, "plant.lsys");
  EXPECT_EQ(roles(line), (std::vector<Role>{{"c.map", io::InputKind::Colormap, 1},
                                           {"plant.view", io::InputKind::View, 1},
                                           {"plant.anim", io::InputKind::Animation, 1}}));
}

TEST(ReferenceCommandLine, SylvaOptionsStayForSylvasParser) {
  ReferenceCommandLine line =
      read({"-M", "m.mat", "p.l", "p.v", "--string", "out.txt", "-o", "x.png", "--verbose", "-ox.obj", "--steps=3"});
  EXPECT_EQ(line.model, "p.l");
  EXPECT_EQ(line.sylva_arguments,
            (std::vector<std::string>{"--string", "out.txt", "-o", "x.png", "--verbose", "-ox.obj", "--steps=3"}));
  EXPECT_EQ(roles(line), (std::vector<Role>{{"m.mat", io::InputKind::Materials, 1}, {"p.v", io::InputKind::View, 1}}));
}

TEST(ReferenceCommandLine, WindowOptionsAreNotedAndIgnored) {
  ReferenceCommandLine line = read({"-a", "-wp", "10", "20", "-wt", "title", "-s100000", "-b", "-rmode", "cont", "m.l"});
  EXPECT_EQ(line.model, "m.l");
  EXPECT_TRUE(line.inputs.empty());
  ASSERT_EQ(line.notes.size(), 5u);  // -b is batch mode, which every Sylva run is
  EXPECT_EQ(line.notes[1], "-wp 10 20: the window position has no meaning without a window; ignored");
  EXPECT_NE(line.notes[2].find("-wt title"), std::string::npos);
  EXPECT_NE(line.notes[3].find("-s100000"), std::string::npos);
  EXPECT_NE(line.notes[4].find("-rmode cont"), std::string::npos);
}

TEST(ReferenceCommandLine, OutputsOfTheReferencePrograms) {
  ReferenceCommandLine lpfg = read({"-b", "m.l", "-out", "m.str", "-w", "640", "480", "-cleanEA20"});
  EXPECT_EQ(lpfg.string_path, "m.str");
  EXPECT_EQ(lpfg.width, 640);
  EXPECT_EQ(lpfg.height, 480);
  EXPECT_TRUE(lpfg.clean_ea20);
  ReferenceCommandLine picture = read({"m.l", "-out", "m.obj"});
  EXPECT_EQ(picture.outputs, std::vector<std::string>{"m.obj"});
  ReferenceCommandLine cpfg = read({"-str", "s.txt", "-png", "p.png", "-rgb", "p.rgb", "m.l", "m.v"});
  EXPECT_EQ(cpfg.string_path, "s.txt");
  EXPECT_EQ(cpfg.outputs, std::vector<std::string>{"p.png"});
  ASSERT_EQ(cpfg.notes.size(), 1u);
  EXPECT_NE(cpfg.notes[0].find("-rgb p.rgb"), std::string::npos);
}

// -h is Sylva's help alone, and cpfg's "string after homomorphism" with files.
TEST(ReferenceCommandLine, HIsHelpOrCpfgsHomomorphismFlag) {
  EXPECT_EQ(read({"-h"}).sylva_arguments, std::vector<std::string>{"-h"});
  ReferenceCommandLine cpfg = read({"-h", "m.l", "m.v"});
  EXPECT_TRUE(cpfg.interpreted_string);
  EXPECT_TRUE(cpfg.sylva_arguments.empty());
}

TEST(ReferenceCommandLine, OfSeveralLSystemsTheLastIsTheModel) {
  ReferenceCommandLine line = read({"a.l", "v.v", "b.l"});
  EXPECT_EQ(line.model, "b.l");
  EXPECT_EQ(roles(line), (std::vector<Role>{{"v.v", io::InputKind::View, 1}}));
  ASSERT_EQ(line.notes.size(), 1u);
  EXPECT_EQ(line.notes[0], "a.l: a second L-system, b.l, replaces it, as in lpfg");
}

TEST(ReferenceCommandLine, AFlagWithoutItsFileIsAnError) {
  EXPECT_THROW(read({"m.l", "-m"}), std::invalid_argument);
  EXPECT_THROW(read({"m.l", "-w", "100"}), std::invalid_argument);
  EXPECT_THROW(read({"m.l", "-w", "wide", "tall"}), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
