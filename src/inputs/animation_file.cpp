#include "inputs/animation_file.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <set>
#include <string_view>

#include "inputs/input_text.h"

namespace sylva::io {

namespace {

std::string warning_at(const std::string& file, const Word& at, const std::string& message) {
  return file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": warning: " + message;
}

// The integer at the start of `text`, as C's %d reads it: a sign and digits,
// the rest ignored, out-of-range values clamped.
std::optional<long long> leading_integer(std::string_view text, std::size_t* used = nullptr) {
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  const std::size_t digits = i;
  long long value = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
    value = std::min<long long>(value * 10 + (text[i] - '0'), 1LL << 40);
    ++i;
  }
  if (i == digits) return std::nullopt;
  if (used) *used = i;
  return negative ? -value : value;
}

int clamp_to_int(long long value) { return static_cast<int>(std::clamp<long long>(value, INT_MIN, INT_MAX)); }

// cpfg's frame intervals: "A-B" or "A", each optionally followed by "step N"
// and by a rotation or scaling of the view ("rotate x y z", "scale x y z"),
// which a run without a window has no use for.
std::vector<FrameInterval> read_intervals(const std::string& path, const std::vector<Word>& words,
                                          std::vector<std::string>& warnings) {
  std::vector<FrameInterval> intervals;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string word = to_lower(words[i].text);
    if (word == "step" && i + 1 < words.size() && !intervals.empty()) {
      if (std::optional<long long> n = leading_integer(words[i + 1].text); n && *n > 0)
        intervals.back().step = clamp_to_int(*n);
      ++i;
      continue;
    }
    if ((word == "rotate" || word == "scale") && !intervals.empty()) {
      i += 3;
      continue;
    }
    std::size_t used = 0;
    std::optional<long long> from = leading_integer(word, &used);
    if (!from) {
      warnings.push_back(warning_at(path, words[i], "expected a frame interval (from-to), found '" + words[i].text +
                                                        "'; ignored"));
      continue;
    }
    FrameInterval interval{clamp_to_int(*from), clamp_to_int(*from), std::nullopt};
    if (used < word.size() && word[used] == '-')
      if (std::optional<long long> to = leading_integer(std::string_view(word).substr(used + 1)))
        interval.to = clamp_to_int(*to);
    intervals.push_back(interval);
  }
  return intervals;
}

}  // namespace

std::vector<int> AnimationFile::frames(int derivation_length) const {
  if (!intervals.empty()) {
    std::set<int> steps;
    // Counted in long long: a step past the last frame may pass INT_MAX.
    for (const FrameInterval& interval : intervals)
      for (long long s = std::max(interval.from, 0); s <= std::min(interval.to, derivation_length);
           s += std::max(interval.step.value_or(step), 1))
        steps.insert(static_cast<int>(s));
    return {steps.begin(), steps.end()};
  }
  std::vector<int> steps;
  int last = std::min(last_frame.value_or(derivation_length), derivation_length);
  for (long long s = std::max(first_frame, 0); s <= last; s += std::max(step, 1)) steps.push_back(static_cast<int>(s));
  return steps;
}

AnimationFile read_animation_file(const std::string& path) {
  std::string text = blank_comments(read_input_file(path, "animation file"));
  AnimationFile animation;
  animation.path = path;
  std::vector<std::string>& warnings = animation.warnings;
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
    const std::string& name = command->name;
    const std::vector<Word>& arguments = command->arguments;
    const Word& value_at = arguments.empty() ? command->end : arguments.front();
    auto unreadable = [&](const std::string& what) {
      warnings.push_back(warning_at(path, value_at,
                                    "expected " + what + " after '" + command->name_word.text + ":', found " +
                                        (arguments.empty() ? "nothing" : "'" + value_at.text + "'") + "; ignored"));
    };
    auto integer = [&](const std::string& what) -> std::optional<long long> {
      std::optional<long long> value = arguments.empty() ? std::nullopt : leading_integer(value_at.text);
      if (!value) unreadable(what);
      return value;
    };
    auto flag = [&](bool& target) {
      std::optional<bool> value = arguments.empty() ? std::nullopt : parse_flag(to_lower(value_at.text));
      if (value) target = *value;
      else unreadable("on or off");
    };
    if (name == "first frame") {
      if (std::optional<long long> n = integer("the first frame")) {
        if (*n < 0) unreadable("a first frame of 0 or more");
        else animation.first_frame = clamp_to_int(*n);
      }
    } else if (name == "last frame") {
      // -1 (as the editors write it) and any negative number: the derivation length.
      if (std::optional<long long> n = integer("the last frame"))
        animation.last_frame = *n < 0 ? std::nullopt : std::optional<int>(clamp_to_int(*n));
    } else if (name == "step") {
      if (std::optional<long long> n = integer("the number of steps between frames")) {
        if (*n < 1) unreadable("a positive number of steps between frames");
        else animation.step = clamp_to_int(*n);
      }
    } else if (name == "swap interval") {
      std::optional<float> value = arguments.empty() ? std::nullopt : parse_float(value_at.text);
      if (!value) {
        if (std::optional<long long> n = integer("the swap interval")) value = static_cast<float>(*n);
      }
      if (value) animation.swap_interval = std::max(*value, 0.0f);
    } else if (name == "frame intervals") {
      animation.intervals = read_intervals(path, arguments, warnings);
      if (!animation.intervals.empty()) {
        animation.first_frame = animation.intervals.front().from;
        animation.last_frame = animation.intervals.back().to;
      }
    } else if (name == "frame numbers") {
      const std::string value = arguments.empty() ? "" : to_lower(value_at.text);
      if (value.rfind("consecutive", 0) == 0) animation.stepno_frame_numbers = false;
      else if (value.rfind("stepno", 0) == 0) animation.stepno_frame_numbers = true;
      else unreadable("consecutive or stepno");
    } else if (name == "frame dump path") {
      std::string dump;
      for (const Word& w : arguments) dump += (dump.empty() ? "" : " ") + w.text;
      animation.frame_dump_path = dump;
    } else if (name == "double buffer") {
      flag(animation.double_buffer);
    } else if (name == "clear between frames") {
      flag(animation.clear_between_frames);
    } else if (name == "center between frames") {
      flag(animation.center_between_frames);
    } else if (name == "hcenter between frames") {
      flag(animation.hcenter_between_frames);
    } else if (name == "scale between frames") {
      flag(animation.scale_between_frames);
    } else if (name == "new view between frames") {
      flag(animation.new_view_between_frames);
    } else if (name == "display on request") {
      flag(animation.display_on_request);
    } else if (name == "end time" || name == "time step") {
      const std::optional<double> value = arguments.empty() ? std::nullopt : parse_double(value_at.text);
      if (!value || !(*value > 0)) unreadable("a positive time");
      else (name == "end time" ? animation.end_time : animation.time_step) = *value;
    } else {
      warnings.push_back(
          warning_at(path, command->name_word, "unknown animation command '" + command->name_word.text + "' ignored"));
    }
  }
  return animation;
}

}  // namespace sylva::io
