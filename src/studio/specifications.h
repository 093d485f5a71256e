// Which panel edits which file, from a vlab object's "specifications" file:
// its menu commands "panel PANELFILE | awkped TARGET" and
// "panel PANELFILE | ped TARGET" (options such as "-rmode cont" allowed on
// either side, spacing and tabs free).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "studio/panel_message.h"

namespace sylva::studio {

struct PanelBinding {
  std::string panel_file;
  std::string target_file;
  ParameterEditor editor = ParameterEditor::Awkped;
  int line = 0;  // of the command in the specifications file
};

// In file order; a command naming a panel twice is listed twice. Lines that
// are not such commands (menu labels, other programs) are passed over.
std::vector<PanelBinding> find_panel_bindings(std::string_view specifications);

}  // namespace sylva::studio
