// The view file's commands after the preprocessor, read in both dialects
// (lpfg's and cpfg's), and what the run takes from the result.
#include <sstream>

#include "fuzz_support.h"
#include "inputs/label_font.h"
#include "inputs/view_parser.h"

namespace {

void read_view(const std::string& text, sylva::io::ViewDialect dialect) {
  sylva::io::ViewFile view;
  view.path = "fuzz.v";
  view.dialect = dialect;
  sylva::io::Parser parser(view);
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number)
    if (std::optional<sylva::io::Command> c = sylva::io::split_command(line, number)) parser.command(*c, view.path);
  parser.finish();
  view.turtle_settings();
  view.tessellation_options();
  view.lights_or_default();
  sylva::io::label_font(view, dialect == sylva::io::ViewDialect::Cpfg);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = sylva::fuzz::text_of(data, size);
  sylva::fuzz::reading([&] { read_view(text, sylva::io::ViewDialect::Lpfg); });
  sylva::fuzz::reading([&] { read_view(text, sylva::io::ViewDialect::Cpfg); });
  return 0;
}
