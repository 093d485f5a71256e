// The font labels are drawn in (Label in lpfg, @L in cpfg), from the view
// file's font: (an X logical font name) or winfont: (name, size, flags).
#pragma once

#include <string>

#include "io/view_file.h"

namespace sylva::io {

struct LabelFont {
  std::string family = "Times";
  float points = 12;  // Qt's point size, as both programs make their QFont
  bool bold = false, italic = false;
  // Pixels at the 96 dots per inch Qt assumes on a desktop.
  float pixels() const { return points * 96.0f / 72.0f; }
};

// lpfg and cpfg read an X font name the same way (lpfg/drawparam.cpp
// Font::Read, cpfg/platformQt.cpp DrawString): split at '-' (an empty field
// before the first one counts), family from field 2 with '_' as spaces,
// weight from 3 (bold and black are bold), italic only when field 4 is
// "italic", the size from field 7 or, when that is not 1..100, field 6; a name
// of fewer fields keeps the default font.
LabelFont parse_x_font(const std::string& name, LabelFont fallback = {});

// The labels' font for a model: winfont: when the view file gives one, else
// font:, else the program's default (lpfg: Times 12; cpfg names courier
// bold 12 in its view-file default).
LabelFont label_font(const ViewFile& view, bool cpfg);

}  // namespace sylva::io
