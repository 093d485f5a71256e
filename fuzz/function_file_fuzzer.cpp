// Function files (.func) and sets (.fset, .tset) in each of the ways they are
// read: lpfg's, timelines, and cpfg's view-file functions (sampled or not);
// each function evaluated as the program it was read for evaluates it.
#include "fuzz_support.h"
#include "geometry/function.h"
#include "inputs/function_file.h"

namespace {

void as_lpfg(const sylva::geometry::Function& f) {
  const sylva::geometry::LpfgFunction lpfg(f);
  lpfg.value(0.3f);
  lpfg.tangent(0.7f);
}

void as_cpfg(const sylva::geometry::Function& f) { sylva::geometry::CpfgFunction(f).value(0.3); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sylva::fuzz::InputFile file;
  const std::string& path = file.holding(data, size);
  sylva::fuzz::reading([&] { as_lpfg(sylva::io::read_function_file(path)); });
  sylva::fuzz::reading([&] {
    for (const sylva::geometry::Function& f : sylva::io::read_function_set_file(path)) as_lpfg(f);
  });
  sylva::fuzz::reading([&] {
    for (const sylva::geometry::Function& f : sylva::io::read_timeline_set_file(path)) as_lpfg(f);
  });
  sylva::fuzz::reading([&] { as_cpfg(sylva::io::read_cpfg_function_file(path)); });
  sylva::fuzz::reading([&] { as_cpfg(sylva::io::read_cpfg_function_file(path, 16)); });
  sylva::fuzz::reading([&] {
    for (const sylva::geometry::Function& f : sylva::io::read_cpfg_function_set_file(path)) as_cpfg(f);
  });
  return 0;
}
