// The cpfg front end after the preprocessor: logical lines, the L-system,
// its expressions and statements, and the C++ generator.
#include "fuzz_support.h"
#include "lang/cpfg_parser.h"
#include "lang/cpp_generator.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sylva::fuzz::reading([&] {
    sylva::lang::generate_cpp(sylva::lang::parse_cpfg(sylva::fuzz::text_of(data, size), "fuzz.l"));
  });
  return 0;
}
