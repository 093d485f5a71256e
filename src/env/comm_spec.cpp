#include "env/comm_spec.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "env/keyword.h"
#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::env {
namespace {

class SpecParser {
 public:
  SpecParser(const std::string& text, const std::string& path) : text_(text) { spec_.path = path; }

  CommSpec parse() {
    std::istringstream lines(text_);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) parse_line(line, ++number);
    // lpfg ("Environment command line not specified") and the communication
    // library ("no executable for field process specified. Environment
    // ignored.") go on without the environment.
    if (spec_.executable.empty())
      spec_.warnings.push_back(spec_.path + ":" + std::to_string(std::max(number, 1)) +
                               ": warning: no 'executable:' names the environmental program; the environment is "
                               "ignored, as lpfg and cpfg ignore it");
    return std::move(spec_);
  }

 private:
  [[noreturn]] void fail(int line, std::size_t offset, const std::string& message) const {
    throw ModelError(SourceLocation{spec_.path, line, offset == std::string::npos ? 0 : static_cast<int>(offset) + 1},
                     message);
  }

  void warn(int line, std::size_t offset, const std::string& message) {
    spec_.warnings.push_back(spec_.path + ":" + std::to_string(line) + ":" + std::to_string(offset + 1) +
                             ": warning: " + message);
  }

  void parse_line(const std::string& line, int number) {
    std::size_t start = 0;
    while (start < line.size() && is_blank(line[start])) ++start;
    if (start == line.size() || line[start] == '#') return;  // blank, or a comment
    const std::size_t colon = line.find(':', start);
    if (colon == std::string::npos) {
      warn(number, start, "not a 'command: value' line; ignored, as lpfg and cpfg ignore it");
      return;
    }
    const std::string command = normalized_keyword(std::string_view(line).substr(start, colon - start));
    std::size_t value_start = colon + 1;
    while (value_start < line.size() && is_blank(line[value_start])) ++value_start;
    std::size_t value_end = line.size();
    while (value_end > value_start && is_blank(line[value_end - 1])) --value_end;
    const std::string value = line.substr(value_start, value_end - value_start);
    const Place at{number, start, value_start};

    if (command == "executable") {
      once(at, command);
      if (value.empty()) {  // the communication library reads no command line and keeps what it had
        warn(number, value_start, "expected the command line of the environmental program; line ignored");
        return;
      }
      spec_.executable = value;
      spec_.executable_line = number;
      spec_.executable_column = static_cast<int>(value_start) + 1;
    } else if (command == "communication type") {
      once(at, command);
      const std::string type = lowercase(value);
      spec_.communication_type = type;
      // The first word names the means; cpfg's may be followed by a number
      // of queries per chunk.
      const std::string means = type.substr(0, type.find_first_of(" \t"));
      if (means != "pipes" && means != "files" && means != "memory" && means != "sockets")
        warn(number, value_start, "unknown communication type '" + value + "'; the communication library uses pipes");
    } else if (command == "turtle position") {
      format(at, command, value, 3, spec_.position);
    } else if (command == "turtle heading") {
      format(at, command, value, 3, spec_.heading);
    } else if (command == "turtle left") {
      format(at, command, value, 3, spec_.left);
    } else if (command == "turtle up") {
      format(at, command, value, 3, spec_.up);
    } else if (command == "turtle line width") {
      format(at, command, value, 1, spec_.line_width);
    } else if (command == "turtle scale factor") {
      format(at, command, value, 1, spec_.scale_factor);
    } else if (command == "following module") {
      once(at, command);
      spec_.following_module = flag(at, value, spec_.following_module);
    } else if (command == "verbose") {
      once(at, command);
      spec_.verbose = flag(at, value, spec_.verbose);
    } else if (command == "interpreted modules") {
      once(at, command);
      spec_.interpreted_modules.clear();
      std::string word;
      for (char c : value + " ") {
        if (is_blank(c) || c == ',') {
          if (!word.empty()) spec_.interpreted_modules.push_back(word);
          word.clear();
        } else {
          word.push_back(c);
        }
      }
    } else {
      warn(number, start,
           "unknown command '" + command +
               "' ignored, as lpfg and cpfg ignore it (they know executable, communication type, turtle position, "
               "turtle heading, turtle left, turtle up, turtle line width, turtle scale factor, following module, "
               "interpreted modules and verbose)");
    }
  }

  struct Place {
    int line;
    std::size_t command;
    std::size_t value;
  };

  // A command given again replaces the first, as in lpfg and cpfg.
  void once(const Place& at, const std::string& command) {
    if (std::find(seen_.begin(), seen_.end(), command) != seen_.end())
      warn(at.line, at.command, "'" + command + ":' is given again; this one replaces the first");
    seen_.push_back(command);
  }

  void format(const Place& at, const std::string& command, const std::string& value, int max_values,
              TurtleFormat& out) {
    once(at, command);
    std::string error;
    std::size_t column = 0;
    if (!parse_turtle_format(value, max_values, out, error, column)) fail(at.line, at.value + column, error);
    if (out.count == 0) fail(at.line, at.value, "expected a format with at least one conversion, such as %g");
  }

  // A switch that is neither on nor off is left as it was, with a warning.
  bool flag(const Place& at, const std::string& value, bool current) {
    if (const std::optional<bool> on = parse_switch(value)) return *on;
    warn(at.line, at.value, "expected yes or no (on or off), not '" + value + "'; left as it was");
    return current;
  }

  const std::string& text_;
  CommSpec spec_;
  std::vector<std::string> seen_;
};

}  // namespace

CommSpec CommSpec::everything() {
  CommSpec spec;
  std::string error;
  std::size_t column = 0;
  parse_turtle_format("%.9g %.9g %.9g", 3, spec.position, error, column);
  spec.heading = spec.left = spec.up = spec.position;
  parse_turtle_format("%.9g", 1, spec.line_width, error, column);
  spec.scale_factor = spec.line_width;
  spec.following_module = true;
  spec.communication_type = "pipes";
  return spec;
}

CommSpec parse_comm_spec(const std::string& text, const std::string& path) { return SpecParser(text, path).parse(); }

CommSpec read_comm_spec(const std::string& path) {
  const WholeFile file = read_whole_file(path);
  if (!file) throw ModelError(SourceLocation{path, 0, 0}, "cannot open the communication specification file");
  return parse_comm_spec(file.bytes, path);
}

}  // namespace sylva::env
