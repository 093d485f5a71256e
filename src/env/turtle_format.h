// The C-like formats of a .e file's "turtle position: P:%.3f %.3f" lines
// (EnviroManual section 2): how many values a field sends, and the text it
// sends them as.
#pragma once

#include <string>
#include <string_view>

namespace sylva::env {

struct TurtleFormat {
  std::string text;  // as written in the .e file, "" when the field is not sent
  int count = 0;     // the conversions that take a value
};

// Parses a format, allowing at most `max_values` conversions. Conversions
// are printf's %[flags][width][.precision]X with X one of f F e E g G a A
// (the value) or d i o u x X (its integer part); %% is a percent sign.
// On error returns false with `error` saying what is wrong and `column` the
// 0-based offset in `text` where it is.
bool parse_turtle_format(std::string_view text, int max_values, TurtleFormat& out, std::string& error,
                         std::size_t& column);

// `format` with its conversions applied to values[0..count).
std::string format_turtle_values(const TurtleFormat& format, const float* values);

}  // namespace sylva::env
