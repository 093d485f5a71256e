// Colormap (.map) and material (.mat) files.
#include "fuzz_support.h"
#include "inputs/palette_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  const std::string& path = file.holding(data, size);
  sylva::fuzz::reading([&] { sylva::io::read_colormap_file(path); });
  sylva::fuzz::reading([&] { sylva::io::read_material_file(path); });
  return 0;
}
