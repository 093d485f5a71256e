// The Virtual Laboratory's panel specification files (VLAB Tools manual,
// 2.4): a header (target, panel name, background, size, font), then blocks
// that each begin with "type: KIND". Both dialects real files use are read:
// the older one, with colour-map indices ("colors: 518 519",
// "background:512"), and the newer one with RGB triples
// ("colors: 255,255,255 255,0,0") and a "target:" line first. Positions,
// sizes, fonts and colours only lay out and paint the panel's own window, so
// they are accepted in either form and not kept.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sylva::studio {

enum class PanelItemKind { Slider, Button, Group, Label, Menu, Page };

struct PanelItem {
  PanelItemKind kind = PanelItemKind::Label;
  // As written; the panel editor keeps names unique by adding "%Copy1" and
  // the like, which groups use to name their buttons.
  std::string name;
  // What the panel shows: the name up to its first '%'.
  std::string display_name;
  int min = 0;  // sliders
  int max = 0;
  // A slider's position; a button's state: 0 off, 1 on, 2 monostable.
  int value = 0;
  std::string message;  // the template sent (sliders, buttons, menus, pages)
  int message_line = 0;  // where the template starts, for its errors
  int message_column = 0;
  std::vector<std::string> buttons;  // a group's button names, as written
  int page = 0;                      // index into PanelFile::pages
  int line = 0;                      // of the item's "type:" line
};

struct PanelFile {
  std::string name;    // "panel name:"
  std::string target;  // "target:", for information only; empty when absent
  // Page names in order. Items before the first PAGE are on a page of
  // their own with an empty name.
  std::vector<std::string> pages;
  std::vector<PanelItem> items;  // in file order, pages included
};

// Throws ModelError at the line and column of the first thing that is not a
// panel specification; `file_name` names the file in that error.
PanelFile read_panel(std::string_view text, const std::string& file_name);

// Whether `text` is a panel specification file rather than, say, an
// L-system that happens to be named panel.l: its first non-blank line is
// "panel name:", or "target:" followed by "panel name:".
bool looks_like_panel(std::string_view text);

}  // namespace sylva::studio
