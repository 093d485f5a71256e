#include "studio/parameters.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "studio/model_defines.h"
#include "studio/panel_file.h"
#include "studio/panel_message.h"
#include "studio/specifications.h"
#include "support/whole_file.h"

namespace sylva::studio {
namespace {

namespace fs = std::filesystem;

struct Binding {
  std::string panel, target;
  ParameterEditor editor = ParameterEditor::Awkped;
};

std::string read_text(const std::string& path) {
  WholeFile file = read_whole_file(path);
  return file ? std::move(file.bytes) : std::string();
}

// Without a specifications file, a panel edits the file of its own kind:
// panel.l the L-system (with awkped), panel.a the animation file, panel.v
// the view file (with ped, as the Virtual Laboratory's objects edit them).
Binding binding_by_kind(const std::string& panel, const std::string& model, const std::vector<io::InputFile>& inputs) {
  const io::InputKind kind = io::input_kind_of(panel);
  for (const io::InputFile& input : inputs)
    if (kind != io::InputKind::Unknown && input.kind == kind) return {panel, input.path, ParameterEditor::Ped};
  return {panel, model, ParameterEditor::Awkped};
}

std::vector<Binding> panel_bindings(const std::string& folder, const std::string& model,
                                    const std::vector<io::InputFile>& inputs) {
  std::vector<Binding> out;
  const std::string specifications = (fs::path(folder) / "specifications").string();
  if (fs::is_regular_file(specifications)) {
    for (const PanelBinding& b : find_panel_bindings(read_text(specifications)))
      out.push_back({(fs::path(folder) / b.panel_file).lexically_normal().string(),
                     (fs::path(folder) / b.target_file).lexically_normal().string(), b.editor});
    if (!out.empty()) return out;
  }
  std::error_code ec;
  std::vector<std::string> panels;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && entry.path().string() != model && entry.file_size(ec) < (1 << 20) &&
        looks_like_panel(read_text(entry.path().string())))
      panels.push_back(entry.path().string());
  std::sort(panels.begin(), panels.end());
  for (const std::string& panel : panels) out.push_back(binding_by_kind(panel, model, inputs));
  return out;
}

// Where a define's current value puts a slider of `scale`, if the file has it.
std::optional<int> file_position(const std::string& target_text, const std::string& define, double scale) {
  for (const ModelDefine& d : find_model_defines(target_text))
    if (d.name == define) return static_cast<int>(std::lround(d.value * scale));
  return std::nullopt;
}

void add_panel_items(const Binding& binding, const PanelFile& panel, std::vector<Parameter>& out) {
  const std::string target_text = read_text(binding.target);
  for (const PanelItem& item : panel.items) {
    if (item.kind != PanelItemKind::Slider && item.kind != PanelItemKind::Button) continue;
    MessageTemplate message;
    try {
      message = parse_message(item.message, {binding.panel, item.message_line, item.message_column});
    } catch (const std::exception&) {
      continue;  // a message no editor takes (a page's, a menu's): nothing to move
    }
    Parameter p;
    p.id = "p" + std::to_string(out.size());
    p.panel = panel.name;
    p.name = item.display_name;
    p.message = item.message;
    p.ped = binding.editor == ParameterEditor::Ped;
    p.target = binding.target;
    p.scale = message.scale;
    if (message.form == MessageTemplate::Form::Define) p.define = message.define;
    if (item.kind == PanelItemKind::Slider) {
      p.min = std::min(item.min, item.max);
      p.max = std::max(item.min, item.max);
      p.value = std::clamp(item.value, p.min, p.max);
    } else {
      p.kind = Parameter::Kind::Button;
      p.min = 0;
      p.max = 1;
      p.value = item.value == 1 ? 1 : 0;  // a monostable button rests off
    }
    // The slider starts where the file is, when the file says.
    if (!p.define.empty() && !message.fixed_value)
      if (std::optional<int> at = file_position(target_text, p.define, p.scale)) p.value = *at;
    p.file_value = p.value;
    out.push_back(std::move(p));
  }
}

// Integer sliders for a model's numeric #defines, in steps of the proposed range.
void add_model_defines(const std::string& model, std::vector<Parameter>& out) {
  for (const ModelDefine& d : find_model_defines(read_text(model))) {
    Parameter p;
    p.id = "p" + std::to_string(out.size());
    p.name = d.name;
    p.define = d.name;
    p.target = model;
    p.define_literal = d.value_text;
    const double step = d.range.step > 0 ? d.range.step : 1;
    p.scale = 1 / step;
    p.min = static_cast<int>(std::lround(d.range.min / step));
    p.max = static_cast<int>(std::lround(d.range.max / step));
    p.value = p.file_value = std::clamp(static_cast<int>(std::lround(d.value / step)), p.min, p.max);
    p.message = "d " + d.name + " %d " + shortest_number_text(p.scale);
    out.push_back(std::move(p));
  }
}

}  // namespace

std::vector<Parameter> find_parameters(const std::string& folder, const std::string& model,
                                       const std::vector<io::InputFile>& inputs, std::vector<std::string>& problems) {
  std::vector<Parameter> out;
  for (const Binding& binding : panel_bindings(folder, model, inputs)) {
    try {
      add_panel_items(binding, read_panel(read_text(binding.panel), binding.panel), out);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
  }
  if (out.empty()) add_model_defines(model, out);
  return out;
}

std::string apply_parameter(const std::string& text, const Parameter& p) {
  if (!p.define_literal.empty()) {
    ModelDefine define;
    define.name = p.define;
    define.value_text = p.define_literal;
    define.integral = p.define_literal.find_first_of(".eEfF") == std::string::npos;
    return set_define(text, p.define, define_value_text(define, p.value / p.scale)).text;
  }
  const MessageTemplate message = parse_message(p.message, {p.target, 0, 0});
  return apply_message(text, message, p.value, p.ped ? ParameterEditor::Ped : ParameterEditor::Awkped).text;
}

}  // namespace sylva::studio
