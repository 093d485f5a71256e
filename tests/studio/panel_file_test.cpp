// Reading vlab panel specification files (VLAB Tools manual, 2.4) in the two
// dialects real files are written in, and telling them from L-systems.
#include <gtest/gtest.h>

#include "studio/panel_file.h"
#include "support/diagnostic.h"

namespace sylva::studio {
namespace {

// The newer dialect: a "target:" line first, RGB colours, a font.
const char* const kRgbPanel =
    "target: Lsystem\n"
    "panel name: L-system params\n"
    "background: 0,0,0\n"
    "size: 217 206\n"
    "font: Arial,14,-1,5,50,0,0,0,0,0\n"
    "\n"
    "type: SLIDER\n"
    "name: Sporangium length x 10\n"
    "colors: 255,255,255 220,77,0\n"
    "origin: 39 83\n"
    "min/max: 0 50\n"
    "value: 30\n"
    "message: d SL %d 10\n"
    "\n"
    "type: LABEL\n"
    "name: Bounding ellipse\n"
    "color: 255,0,0\n"
    "origin: 44 20\n";

TEST(PanelFile, ReadsTheRgbDialect) {
  const PanelFile panel = read_panel(kRgbPanel, "panel.l");
  EXPECT_EQ(panel.name, "L-system params");
  EXPECT_EQ(panel.target, "Lsystem");
  ASSERT_EQ(panel.pages, std::vector<std::string>{""});
  ASSERT_EQ(panel.items.size(), 2u);

  const PanelItem& slider = panel.items[0];
  EXPECT_EQ(slider.kind, PanelItemKind::Slider);
  EXPECT_EQ(slider.name, "Sporangium length x 10");
  EXPECT_EQ(slider.display_name, "Sporangium length x 10");
  EXPECT_EQ(slider.min, 0);
  EXPECT_EQ(slider.max, 50);
  EXPECT_EQ(slider.value, 30);
  EXPECT_EQ(slider.message, "d SL %d 10");
  EXPECT_EQ(slider.message_line, 13);
  EXPECT_EQ(slider.message_column, 10);
  EXPECT_EQ(slider.page, 0);
  EXPECT_EQ(slider.line, 7);

  const PanelItem& label = panel.items[1];
  EXPECT_EQ(label.kind, PanelItemKind::Label);
  EXPECT_EQ(label.name, "Bounding ellipse");
  EXPECT_EQ(label.line, 15);
}

// The older dialect: no target, colour-map indices, "background:512" without
// a blank; written here with CRLF line ends, trailing blanks and blank lines
// inside an item.
TEST(PanelFile, ReadsTheColourIndexDialectWithCrlfAndTrailingBlanks) {
  const PanelFile panel = read_panel(
      "panel name: Viewing \r\n"
      "background:512\r\n"
      "size: 170 250\r\n"
      "\r\n"
      "type: SLIDER  \r\n"
      "name: Line width\t\r\n"
      "colors: 513 514\r\n"
      "\r\n"
      "origin: 20 60\r\n"
      "min/max: -5 5 \r\n"
      "value: -2\r\n"
      "message: n 4 1 0 %d \r\n"
      "\r\n"
      "type: BUTTON\r\n"
      "name: Width decr\r\n"
      "colors: 515 516\r\n"
      "origin: 35 20\r\n"
      "value: 2\r\n"
      "message: n 5 1 0 %d\r\n",
      "panel.v");
  EXPECT_EQ(panel.name, "Viewing");
  EXPECT_EQ(panel.target, "");
  ASSERT_EQ(panel.items.size(), 2u);
  EXPECT_EQ(panel.items[0].kind, PanelItemKind::Slider);
  EXPECT_EQ(panel.items[0].name, "Line width");
  EXPECT_EQ(panel.items[0].min, -5);
  EXPECT_EQ(panel.items[0].max, 5);
  EXPECT_EQ(panel.items[0].value, -2);
  EXPECT_EQ(panel.items[0].message, "n 4 1 0 %d");
  EXPECT_EQ(panel.items[0].line, 5);
  EXPECT_EQ(panel.items[1].kind, PanelItemKind::Button);
  EXPECT_EQ(panel.items[1].name, "Width decr");
  EXPECT_EQ(panel.items[1].value, 2);  // monostable
  EXPECT_EQ(panel.items[1].line, 14);
}

TEST(PanelFile, GroupsNameTheirButtonsAsWrittenAndShowNamesWithoutCopySuffixes) {
  const PanelFile panel = read_panel(
      "target: Lsystem\n"
      "panel name: L-system\n"
      "size: 178 505\n"
      "type: BUTTON\n"
      "name: Right\n"
      "tricolor: 255,255,255 0,0,255 0,0,0\n"
      "origin: 36 18\n"
      "value: 1\n"
      "message: d LEFT 0 1\n"
      "type: BUTTON\n"
      "name: Right%Copy1\n"
      "tricolor: 255,255,255 0,0,255 0,0,0\n"
      "origin: 36 47\n"
      "value: 0\n"
      "message: d DIR 1 1\n"
      "\n"
      "type: GROUP\n"
      "color: 255,255,255\n"
      "Right\n"
      "Right%Copy1\n"
      "ENDGROUP\n",
      "panel.l");
  ASSERT_EQ(panel.items.size(), 3u);
  EXPECT_EQ(panel.items[1].name, "Right%Copy1");
  EXPECT_EQ(panel.items[1].display_name, "Right");
  EXPECT_EQ(panel.items[1].message, "d DIR 1 1");
  const PanelItem& group = panel.items[2];
  EXPECT_EQ(group.kind, PanelItemKind::Group);
  EXPECT_EQ(group.buttons, (std::vector<std::string>{"Right", "Right%Copy1"}));
  EXPECT_EQ(group.line, 17);

  // A group written without its colour line.
  const PanelFile bare = read_panel("panel name: P\nsize: 1 1\ntype: GROUP\nA\nB\nENDGROUP\n", "p");
  EXPECT_EQ(bare.items[0].buttons, (std::vector<std::string>{"A", "B"}));
}

TEST(PanelFile, ItemsBelongToThePageBeforeThem) {
  const PanelFile panel = read_panel(
      "target: Lsystem\n"
      "panel name: L-system\n"
      "size: 192 590\n"
      "type: PAGE\n"
      "name: Set 1\n"
      "color: 255,255,255\n"
      "origin: 67 570\n"
      "message: d NOTHING %d 1\n"
      "type: LABEL\n"
      "name: On the first page\n"
      "origin: 1 1\n"
      "type: PAGE\n"
      "name: Set 2\n"
      "message: d NOTHING %d 1\n"
      "type: MENU\n"
      "name: \n"
      "message: d <name> %d <scale>\n",
      "panel.l");
  EXPECT_EQ(panel.pages, (std::vector<std::string>{"Set 1", "Set 2"}));
  ASSERT_EQ(panel.items.size(), 4u);
  EXPECT_EQ(panel.items[0].kind, PanelItemKind::Page);
  EXPECT_EQ(panel.items[0].page, 0);
  EXPECT_EQ(panel.items[0].message, "d NOTHING %d 1");
  EXPECT_EQ(panel.items[1].page, 0);
  EXPECT_EQ(panel.items[2].kind, PanelItemKind::Page);
  EXPECT_EQ(panel.items[2].page, 1);
  EXPECT_EQ(panel.items[3].kind, PanelItemKind::Menu);
  EXPECT_EQ(panel.items[3].name, "");
  EXPECT_EQ(panel.items[3].page, 1);
}

TEST(PanelFile, APanelWithNoItemsHasNoPages) {
  const PanelFile panel = read_panel("panel name: Empty\nsize: 100 100\n", "p");
  EXPECT_EQ(panel.name, "Empty");
  EXPECT_TRUE(panel.pages.empty());
  EXPECT_TRUE(panel.items.empty());
}

std::string error_of(const std::string& text) {
  try {
    read_panel(text, "panel.l");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PanelFile, ErrorsNameTheLineAndWhatWasExpected) {
  const std::string header = "panel name: P\nsize: 10 10\n";  // lines 1-2
  EXPECT_EQ(error_of("size: 10 10\ntype: LABEL\nname: x\n"),
            "panel.l:2:1: error: expected 'panel name:' in the panel header");
  EXPECT_EQ(error_of("panel name: P\nbackgrond: 0,0,0\n"),
            "panel.l:2:1: error: expected a panel header keyword (target:, panel name:, background:, size:, font:, "
            "colourmap:), found 'backgrond:'");
  EXPECT_EQ(error_of(header + "type: KNOB\n"),
            "panel.l:3:7: error: expected SLIDER, BUTTON, GROUP, LABEL, MENU or PAGE, found 'KNOB'");
  EXPECT_EQ(error_of(header + "type: SLIDER\nname: s\nvalue: 1\nmessage: d S %d 1\n"),
            "panel.l:3:1: error: expected a 'min/max:' line in the SLIDER that begins here");
  EXPECT_EQ(error_of(header + "type: SLIDER\nname: s\nmin/max: 1 x\nvalue: 1\nmessage: d S %d 1\n"),
            "panel.l:5:10: error: expected 2 integers after 'min/max:'");
  EXPECT_EQ(error_of(header + "type: BUTTON\nname: b\nvalue: 1.5\nmessage: d B 1 1\n"),
            "panel.l:5:8: error: expected an integer after 'value:'");
  EXPECT_EQ(error_of(header + "type: LABEL\nname: a\n\nname: b\n"),
            "panel.l:6:1: error: a second 'name:' in one LABEL (expected 'type:' to begin the next item)");
  EXPECT_EQ(error_of(header + "type: MENU\nname: m\nmin/max: 1 2\n"),
            "panel.l:5:1: error: expected name:, message: or type: in a MENU, found 'min/max:'");
  EXPECT_EQ(error_of(header + "type: LABEL\njust words\n"), "panel.l:4:1: error: expected 'keyword: value'");
  EXPECT_EQ(error_of(header + "type: GROUP\nA\nB\n"),
            "panel.l:3:1: error: expected 'ENDGROUP' to close the GROUP that begins here");
}

TEST(PanelFile, LooksLikePanelSniffsTheHeaderNotTheName) {
  EXPECT_TRUE(looks_like_panel("target: Lsystem\npanel name: L-system\n"));
  EXPECT_TRUE(looks_like_panel("\n  \r\npanel name: Viewing\r\nbackground:512\r\n"));
  EXPECT_FALSE(looks_like_panel("#define STEPS 8\nLsystem: 1\nderivation length: STEPS\n"));
  EXPECT_FALSE(looks_like_panel("/* panel name: not a panel */\n"));
  EXPECT_FALSE(looks_like_panel("target: plant\nderivation length: 3\n"));
  EXPECT_FALSE(looks_like_panel(""));
}

}  // namespace
}  // namespace sylva::studio
