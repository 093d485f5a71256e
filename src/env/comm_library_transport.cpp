#include "env/comm_library_transport.h"

#include <cstdio>
#include <algorithm>
#include <cstdlib>

#include "env/turtle_format.h"

namespace sylva::env {
namespace {

// A number as the sender prints it and the receiver reads it back (atof).
float through_text(float value, const char* format) {
  char text[512];
  std::snprintf(text, sizeof text, format, static_cast<double>(value));
  return static_cast<float>(std::atof(text));
}

// The characters before a format's first conversion ('%' not followed by
// '%'): what the communication library skips before reading the numbers.
std::size_t text_before_first_conversion(const std::string& format) {
  for (std::size_t at = 0; at < format.size(); ++at) {
    if (format[at] != '%') continue;
    if (at + 1 < format.size() && format[at + 1] == '%') {
      ++at;
      continue;
    }
    return at;
  }
  return format.size();
}

// One turtle field printed with its format and read back as the library
// reads it: up to `size` numbers after the skipped prefix, into `kept`,
// whose values sscanf does not reach stay as the previous query left them.
void through_format(const TurtleFormat& format, const float* now, float* kept, int size) {
  if (format.count == 0) return;
  const std::string text = format_turtle_values(format, now);
  const std::size_t skip = text_before_first_conversion(format.text);
  const char* numbers = text.c_str() + std::min(skip, text.size());
  if (size == 1) std::sscanf(numbers, "%f", &kept[0]);
  else std::sscanf(numbers, "%f %f %f", &kept[0], &kept[1], &kept[2]);
}

class CommLibraryTransport : public Field {
 public:
  CommLibraryTransport(std::unique_ptr<Field> program, const CommSpec& spec, ModelingProgram master,
                       std::function<void(const std::string&)> warn)
      : program_(std::move(program)), spec_(spec), master_(master), warn_(std::move(warn)) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<Query> sent(queries.begin(), queries.end());
    for (Query& query : sent) {
      carry_parameters(query.module);
      carry_parameters(query.following);
      carry_turtle(query.turtle);
    }
    std::vector<Answer> replies(answers.size());
    program_->answer(sent, replies, step);
    std::size_t dropped = 0;
    for (std::size_t k = 0; k < replies.size(); ++k)
      if (!accept(queries[k], replies[k], answers[k])) ++dropped;
    if (dropped > 0) {
      const std::string where = master_ == ModelingProgram::lpfg
                                    ? "lpfg drops an answer unless it gives E1 one value and E2 two"
                                    : "cpfg drops the values beyond a ?E's parameters";
      const std::string message = "warning: " + std::to_string(dropped) + " answer" + (dropped == 1 ? "" : "s") +
            " of the environmental program ignored in the pass before step " + std::to_string(step + 1) + " (" +
            where + ")\n";
      if (warn_) warn_(message);
      else std::fputs(message.c_str(), stderr);
    }
  }

  void finish() override { program_->finish(); }

 private:
  void carry_parameters(ModuleRecord& module) const {
    const char* format = master_ == ModelingProgram::lpfg ? "%f" : "%g";
    for (float& value : module.parameters) value = through_text(value, format);
  }

  void carry_turtle(TurtleReport& turtle) {
    TurtleReport& kept = last_turtle_;
    through_format(spec_.position, turtle.position.data(), kept.position.data(), 3);
    through_format(spec_.heading, turtle.heading.data(), kept.heading.data(), 3);
    through_format(spec_.left, turtle.left.data(), kept.left.data(), 3);
    through_format(spec_.up, turtle.up.data(), kept.up.data(), 3);
    through_format(spec_.line_width, &turtle.line_width, &kept.line_width, 1);
    through_format(spec_.scale_factor, &turtle.scale_factor, &kept.scale_factor, 1);
    if (spec_.position.count) turtle.position = kept.position;
    if (spec_.heading.count) turtle.heading = kept.heading;
    if (spec_.left.count) turtle.left = kept.left;
    if (spec_.up.count) turtle.up = kept.up;
    if (spec_.line_width.count) turtle.line_width = kept.line_width;
    if (spec_.scale_factor.count) turtle.scale_factor = kept.scale_factor;
  }

  // Writes what the modeling program keeps of `reply` into `answer`; false
  // when it drops some or all of it.
  bool accept(const Query& query, const Answer& reply, Answer& answer) const {
    int sent = 0;  // the parameters the program answered
    for (int i = 0; i < kMaxParameters; ++i)
      if (reply.set.test(static_cast<std::size_t>(i))) sent = i + 1;
    if (sent == 0) return true;
    const int count = static_cast<int>(query.module.parameters.size());
    if (master_ == ModelingProgram::lpfg) {
      const std::string& symbol = query.module.symbol;
      const bool fits = symbol == "E1" ? sent == 1 : symbol == "E2" ? sent == 2 : sent <= count;
      if (!fits) return false;
      for (int i = 0; i < sent; ++i)
        answer.assign(i, reply.set.test(static_cast<std::size_t>(i)) ? through_text(reply.value[i], "%g") : 0.0f);
      return true;
    }
    for (int i = 0; i < sent && i < count; ++i)
      if (reply.set.test(static_cast<std::size_t>(i))) answer.assign(i, through_text(reply.value[i], "%g"));
    return sent <= count;
  }

  std::unique_ptr<Field> program_;
  CommSpec spec_;
  ModelingProgram master_;
  std::function<void(const std::string&)> warn_;
  TurtleReport last_turtle_;
};

}  // namespace

std::unique_ptr<Field> through_comm_library(std::unique_ptr<Field> program, const CommSpec& spec,
                                            ModelingProgram master, std::function<void(const std::string&)> warn) {
  return std::make_unique<CommLibraryTransport>(std::move(program), spec, master, std::move(warn));
}

}  // namespace sylva::env
