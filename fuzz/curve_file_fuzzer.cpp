// cpfg's curve files (a view file's "curve:"), and the curve sampled.
#include "fuzz_support.h"
#include "inputs/curve_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  sylva::fuzz::reading([&] {
    const sylva::geometry::Contour curve = sylva::io::read_curve_file(file.holding(data, size));
    curve.resample(8);
    curve.at_parameter(0.5);
  });
  return 0;
}
