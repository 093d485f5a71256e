// The animation file (.a), and the frames it selects.
#include "fuzz_support.h"
#include "inputs/animation_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  sylva::fuzz::reading([&] { sylva::io::read_animation_file(file.holding(data, size)).frames(100); });
  return 0;
}
