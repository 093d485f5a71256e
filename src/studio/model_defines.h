// A model's numeric #defines, offered as sliders when it has no panel. Only
// the defines that awkped's "d NAME VALUE" edit can write back are listed:
// "#define NAME number" lines, the number the line's third word, with at
// most a comment after it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sylva::studio {

// A proposed slider for a value:
//   integers  v >= 0: 0 .. max(10, 2v), step 1
//             v <  0: -m .. m with m = max(10, -2v), step 1
//   floating  step 10^(floor(log10 |v|) - 2), so the slider moves in the
//             value's third significant digit, or finer where v has more
//             decimals (137.51: 0.01), so that v is one of the slider's
//             positions; 0 .. 2v for v > 0 and -2|v| .. 2|v| for v < 0, both
//             ends multiples of the step; 0.0 gives 0 .. 1 in steps of 0.01
struct SliderRange {
  double min = 0;
  double max = 0;
  double step = 1;
};

struct ModelDefine {
  std::string name;
  std::string value_text;  // as written, suffix included: "1.5f"
  double value = 0;
  bool integral = false;  // written without '.', exponent or 'f'
  int line = 0;           // 1-based
  SliderRange range;
};

// The source's numeric object-like #defines in file order, each name once
// (at its first definition: awkped rewrites them all alike). Skipped: those
// in comments or in "#if 0" blocks, function-like ones, ones whose value is
// not a single number, names beginning with '_' (include guards and the
// implementation's own), and mathematical constants (a value within 1e-4 of
// pi, 2pi, pi/2, pi/180, 180/pi or e).
std::vector<ModelDefine> find_model_defines(std::string_view source);

SliderRange propose_slider_range(double value, bool integral);

// `value` as the define's new text, keeping it the same kind of literal: a
// floating define stays floating ("2.0", suffix kept: "2.5f"), an integral
// one is rounded to an integer.
std::string define_value_text(const ModelDefine& define, double value);

}  // namespace sylva::studio
