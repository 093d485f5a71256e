// A saved string read back, with modules of every parameter type the runtime
// reads (numbers, vectors, flags, bytes, arrays).
#include "fuzz_support.h"
#include "io/string_reader.h"
#include "sylva/runtime/modules.h"

namespace {

const sylva::ModuleTypes& types() {
  auto entry = [](const sylva::abi::ModuleType& t) {
    return sylva::ModuleTypes::Type{t.name, t.param_size, t.format_params, t.param_count, t.parse_params};
  };
  using namespace sylva;
  static const ModuleTypes all({entry(rt::module_type<float, int, V3f, bool, double>("A")),
                                entry(rt::module_type<>("B")),
                                entry(rt::module_type<V2d, unsigned char, float[2]>("C")),
                                entry(rt::module_type<float>("F")),
                                entry(rt::module_type<int, int>("SB")),
                                entry(rt::module_type<V3d, V2f, char, long>("D"))});
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sylva::fuzz::reading([&] {
    const sylva::ModuleString s = sylva::io::parse_string(sylva::fuzz::text_of(data, size), types(), "fuzz.str");
    s.count_modules(types());
  });
  return 0;
}
