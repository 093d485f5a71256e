// Run by the build: `sylva_precompile_runtime OUTPUT RUNTIME COMPILER`
// precompiles RUNTIME/lpfgall.h for models compiled by COMPILER
// (build::precompile_runtime). A compiler that cannot leaves an empty OUTPUT,
// which models go without.
#include <cstdio>
#include <fstream>

#include "build/model_builder.h"
#include "support/diagnostic.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s OUTPUT RUNTIME COMPILER\n", argv[0]);
    return 2;
  }
  try {
    sylva::build::precompile_runtime(argv[1], argv[2], argv[3]);
  } catch (const sylva::ModelError& e) {
    std::fprintf(stderr, "warning: models will be compiled without a precompiled runtime header: %s\n", e.what());
    std::ofstream(argv[1], std::ios::trunc);
  }
  return 0;
}
