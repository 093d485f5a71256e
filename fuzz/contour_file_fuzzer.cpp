// Contour files (.con) and contour sets (.cset), and the contour sampled as
// a generalized cylinder samples it.
#include "fuzz_support.h"
#include "inputs/contour_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  const std::string& path = file.holding(data, size);
  sylva::fuzz::reading([&] {
    const sylva::geometry::Contour contour = sylva::io::read_contour_file(path);
    contour.resample(8);
    contour.at_parameter(0.5);
  });
  sylva::fuzz::reading([&] { sylva::io::read_contour_set_file(path); });
  return 0;
}
