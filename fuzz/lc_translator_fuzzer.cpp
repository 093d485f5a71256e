// The L+C front end after the preprocessor: the lexer, the parser and the C++
// generator, on preprocessed text (line markers and all) as g++ -E gives it.
#include "fuzz_support.h"
#include "lang/cpp_generator.h"
#include "lang/lc_parser.h"
#include "lang/token.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sylva::fuzz::reading([&] {
    const sylva::lang::TokenStream tokens = sylva::lang::tokenize_preprocessed(sylva::fuzz::text_of(data, size));
    sylva::lang::generate_cpp(sylva::lang::parse_lc(tokens, "fuzz.l"));
  });
  return 0;
}
