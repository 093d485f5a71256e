// The values a modeller moves in the studio's parameter panel: the items of
// the model's Virtual Laboratory panels (panel_file.h) or, when it has none,
// its numeric #defines (model_defines.h). Either way a parameter is an
// integer on a slider (or a button's 0/1) and a message template that says
// how that integer goes into which file (panel_message.h): `d NAME %d SCALE`
// sets `#define NAME` to value/SCALE, as awkped does.
#pragma once

#include <string>
#include <vector>

#include "inputs/input_files.h"

namespace sylva::studio {

struct Parameter {
  std::string id;       // "p0", "p1" ... in panel order
  std::string panel;    // the panel's name ("" for the model's defines)
  enum class Kind { Slider, Button } kind = Kind::Slider;
  std::string name;     // as the panel shows it
  std::string define;   // the #define it sets, when it sets one
  int min = 0, max = 10, step = 1;
  int value = 0;        // what the slider shows now
  int file_value = 0;   // what the file says
  std::string message;  // the panel's message template ("d WIDTH %d 10")
  bool ped = false;     // edited by ped (panel | ped FILE), not awkped
  std::string target;   // the file the message edits
  double scale = 1;     // what the define receives is value / scale
  // A model's own define (no panel): its literal as written, whose kind
  // (integer, floating, 'f' suffix) the new value keeps.
  std::string define_literal;
  bool modified() const { return value != file_value; }
};

// The parameters of the model `model` in `folder`, with inputs `inputs`: from
// the panel files that the object's `specifications` names (or, without one,
// every panel file in the folder, each editing the file of its kind among the
// model and its inputs), or else from the model's numeric #defines. Panel
// files that cannot be read are skipped, their error in `problems`.
std::vector<Parameter> find_parameters(const std::string& folder, const std::string& model,
                                       const std::vector<io::InputFile>& inputs, std::vector<std::string>& problems);

// `text` (the content of parameter.target) with `parameter`'s value applied.
std::string apply_parameter(const std::string& text, const Parameter& parameter);

}  // namespace sylva::studio
