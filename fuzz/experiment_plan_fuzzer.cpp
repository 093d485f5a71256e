// Experiment plans (TOML): the reader's checks of keys, types and value
// ranges. The plans name "m.l", a model file made once beside them.
#include <filesystem>
#include <fstream>

#include "experiment/plan.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string dir = [] {
    const std::filesystem::path d = std::filesystem::temp_directory_path() / "sylva-fuzz-plan";
    std::filesystem::create_directories(d);
    std::ofstream(d / "m.l") << "#define ANGLE 30\n";
    return d.string();
  }();
  const std::string text = sylva::fuzz::text_of(data, size);
  sylva::fuzz::reading([&] { sylva::experiment::parse_plan(text, dir + "/plan.toml"); });
  return 0;
}
