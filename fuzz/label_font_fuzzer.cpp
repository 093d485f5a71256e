// X logical font names (a view file's font:).
#include "fuzz_support.h"
#include "inputs/label_font.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sylva::fuzz::reading([&] { sylva::io::parse_x_font(sylva::fuzz::text_of(data, size)); });
  return 0;
}
