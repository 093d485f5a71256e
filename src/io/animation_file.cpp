#include "io/animation_file.h"

#include <algorithm>
#include <string_view>

#include "io/input_text.h"

namespace sylva::io {

namespace {

std::string warning_at(const std::string& file, const Word& at, const std::string& message) {
  return file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": warning: " + message;
}

int non_negative(WordReader& in, std::string_view what) {
  Word at = in.peek();
  int value = in.integer(what);
  if (value < 0) in.fail(at, "expected " + std::string(what) + " (0 or more), found '" + at.text + "'");
  return value;
}

}  // namespace

std::vector<int> AnimationFile::frames(int derivation_length) const {
  std::vector<int> steps;
  int last = std::min(last_frame.value_or(derivation_length), derivation_length);
  for (int s = std::max(first_frame, 0); s <= last; s += std::max(step, 1)) steps.push_back(s);
  return steps;
}

AnimationFile read_animation_file(const std::string& path) {
  std::string text = blank_comments(read_input_file(path, "animation file"));
  AnimationFile animation;
  animation.path = path;
  std::size_t start = 0;
  int line_number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    start = end + 1;
    ++line_number;
    std::optional<Command> command = split_command(line, line_number);
    if (!command) continue;
    WordReader in(path, command->arguments, command->end);
    const std::string& name = command->name;
    auto flag = [&](bool& target) {
      Word at = in.next("on or off after '" + command->name_word.text + ":'");
      std::optional<bool> value = parse_flag(at.text);
      if (!value) in.fail(at, "expected on or off after '" + command->name_word.text + ":', found '" + at.text + "'");
      target = *value;
    };
    if (name == "first frame") {
      animation.first_frame = non_negative(in, "the first frame");
    } else if (name == "last frame") {
      animation.last_frame = non_negative(in, "the last frame");
    } else if (name == "step") {
      Word at = in.peek();
      animation.step = in.integer("the number of steps between frames");
      if (animation.step < 1) in.fail(at, "expected a positive number of steps between frames, found '" + at.text + "'");
    } else if (name == "swap interval") {
      Word at = in.peek();
      animation.swap_interval = in.number("the swap interval");
      if (animation.swap_interval < 0) in.fail(at, "expected a swap interval of 0 or more, found '" + at.text + "'");
    } else if (name == "double buffer") {
      flag(animation.double_buffer);
    } else if (name == "clear between frames") {
      flag(animation.clear_between_frames);
    } else if (name == "hcenter between frames") {
      flag(animation.hcenter_between_frames);
    } else if (name == "scale between frames") {
      flag(animation.scale_between_frames);
    } else if (name == "new view between frames") {
      flag(animation.new_view_between_frames);
    } else if (name == "display on request") {
      flag(animation.display_on_request);
    } else {
      animation.warnings.push_back(
          warning_at(path, command->name_word, "unknown animation command '" + command->name_word.text + "' ignored"));
      continue;
    }
    if (!in.at_end())
      animation.warnings.push_back(warning_at(path, in.peek(), "'" + in.peek().text + "' after the value ignored"));
  }
  return animation;
}

}  // namespace sylva::io
