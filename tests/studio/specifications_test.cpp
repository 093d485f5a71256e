// Which panel edits which file, from a vlab object's specifications file.
#include <gtest/gtest.h>

#include "studio/specifications.h"

namespace sylva::studio {
namespace {

TEST(Specifications, FindsPanelsPipedIntoAwkpedAndPed) {
  const std::vector<PanelBinding> bindings = find_panel_bindings(
      "plant.l\n"                                             // 1
      "panel.l\n"                                             // 2
      "ignore:\n"                                             // 3
      "*\n"                                                   // 4
      "plant:\n"                                              // 5
      "\tgenerate:\n"                                         // 6
      "\t\tcpfg -m plant.map plant.l plant.v plant.a\n"       // 7
      "L-system:\n"                                           // 8
      "\tpanel:\n"                                            // 9
      "\t\tdisplay:\n"                                        // 10
      "\t\t\tpanel panel.l | awkped plant.l\n"                // 11
      "\t\tEDIT panel.l\n"                                    // 12
      "animate:\n"                                            // 13
      "\tpanel:\n"                                            // 14
      "\t\tpanel\tpanel.a|ped  plant.a \r\n"                  // 15
      "\tpanel -rmode cont -wp 10 20 view.pnl | awkped -lstudio view.v\n"  // 16
      "\tpanel panel.l plant.l | awkped plant.l\n"            // 17
      "\ttimeline -rmode cont functions.tset | awkped aging.vset\n"  // 18
      "\tpanel panel.x | sed s/a/b/\n");                      // 19
  ASSERT_EQ(bindings.size(), 4u);
  EXPECT_EQ(bindings[0].panel_file, "panel.l");
  EXPECT_EQ(bindings[0].target_file, "plant.l");
  EXPECT_EQ(bindings[0].editor, ParameterEditor::Awkped);
  EXPECT_EQ(bindings[0].line, 11);

  EXPECT_EQ(bindings[1].panel_file, "panel.a");
  EXPECT_EQ(bindings[1].target_file, "plant.a");
  EXPECT_EQ(bindings[1].editor, ParameterEditor::Ped);
  EXPECT_EQ(bindings[1].line, 15);

  EXPECT_EQ(bindings[2].panel_file, "view.pnl");
  EXPECT_EQ(bindings[2].target_file, "view.v");
  EXPECT_EQ(bindings[2].editor, ParameterEditor::Awkped);

  // panel opens its first file argument.
  EXPECT_EQ(bindings[3].panel_file, "panel.l");
  EXPECT_EQ(bindings[3].target_file, "plant.l");
  EXPECT_EQ(bindings[3].line, 17);
}

TEST(Specifications, NoPanelsInAnObjectWithoutThem) {
  EXPECT_TRUE(find_panel_bindings("").empty());
  EXPECT_TRUE(find_panel_bindings("lsystem.l\n*\nrun:\n\tlpfg lsystem.l view.v\n").empty());
}

}  // namespace
}  // namespace sylva::studio
