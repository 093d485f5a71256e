// cpfg's background scene files after the preprocessor, with and without a
// material file.
#include <sstream>

#include "fuzz_support.h"
#include "inputs/background_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<sylva::io::PreprocessedLine> lines;
  std::istringstream text(sylva::fuzz::text_of(data, size));
  std::string line;
  for (int number = 1; std::getline(text, line); ++number) lines.push_back({"fuzz.scene", number, line});
  sylva::fuzz::reading([&] { sylva::io::parse_background_scene(lines, false); });
  sylva::fuzz::reading([&] { sylva::io::parse_background_scene(lines, true); });
  return 0;
}
