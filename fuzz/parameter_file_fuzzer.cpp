// Parameter files (.vset).
#include "fuzz_support.h"
#include "inputs/parameter_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  sylva::fuzz::reading([&] { sylva::io::read_parameter_file(file.holding(data, size)); });
  return 0;
}
