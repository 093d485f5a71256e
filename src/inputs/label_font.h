// The labels' font (Label in lpfg, @L in cpfg) from the view file's font:
// (an X logical font name) or winfont: (name, size, flags).
#pragma once

#include <string>

#include "geometry/render_settings.h"
#include "inputs/view_file.h"

namespace sylva::io {

// lpfg and cpfg read an X font name the same way (lpfg/drawparam.cpp
// Font::Read, cpfg/platformQt.cpp DrawString): split at '-' (an empty field
// before the first one counts), family from field 2 with '_' as spaces,
// weight from 3 (bold and black are bold), italic only when field 4 is
// "italic", the size from field 7 or, when that is not 1..100, field 6; a name
// of fewer fields keeps the default font.
geometry::LabelFont parse_x_font(const std::string& name, geometry::LabelFont fallback = {});

// The labels' font for a model: winfont: when the view file gives one, else
// font:, else the program's default (lpfg: Times 12; cpfg names courier
// bold 12 in its view-file default).
geometry::LabelFont label_font(const ViewFile& view, bool cpfg);

}  // namespace sylva::io
