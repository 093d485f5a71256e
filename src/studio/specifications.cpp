#include "studio/specifications.h"

#include <optional>

#include "studio/text_lines.h"

namespace sylva::studio {

namespace {

// "panel" or "/some/bin/panel".
bool is_program(std::string_view word, std::string_view program) {
  const std::size_t slash = word.rfind('/');
  return (slash == std::string_view::npos ? word : word.substr(slash + 1)) == program;
}

// How many arguments follow each of panel's options (its window placement
// and refresh mode); other options stand alone.
std::size_t option_arguments(std::string_view option) {
  if (option == "-rmode" || option == "-refreshMode") return 1;
  if (option == "-wp" || option == "-wpr" || option == "-wr" || option == "-ws") return 2;
  return 0;
}

// The first argument after the program that is not an option.
std::optional<std::string_view> first_operand(const std::vector<std::string_view>& words) {
  for (std::size_t i = 1; i < words.size(); ++i) {
    if (words[i][0] != '-') return words[i];
    i += option_arguments(words[i]);
  }
  return std::nullopt;
}

}  // namespace

std::vector<PanelBinding> find_panel_bindings(std::string_view specifications) {
  std::vector<PanelBinding> bindings;
  for (const TextLine& line : split_lines(specifications)) {
    const std::size_t pipe = line.text.find('|');
    if (pipe == std::string_view::npos) continue;
    const std::vector<std::string_view> panel = split_words(line.text.substr(0, pipe));
    std::string_view rest = line.text.substr(pipe + 1);
    const std::vector<std::string_view> editor = split_words(rest.substr(0, rest.find('|')));
    if (panel.empty() || editor.empty() || !is_program(panel[0], "panel")) continue;
    const bool ped = is_program(editor[0], "ped");
    if (!ped && !is_program(editor[0], "awkped")) continue;
    const std::optional<std::string_view> panel_file = first_operand(panel);
    const std::optional<std::string_view> target = first_operand(editor);
    if (!panel_file || !target) continue;
    bindings.push_back({std::string(*panel_file), std::string(*target),
                        ped ? ParameterEditor::Ped : ParameterEditor::Awkped, line.number});
  }
  return bindings;
}

}  // namespace sylva::studio
