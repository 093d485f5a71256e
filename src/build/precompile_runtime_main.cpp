// Run by the build: `sylva_precompile_runtime OUTPUT` precompiles the runtime's
// lpfgall.h for models (build::precompile_runtime). A compiler that cannot
// (not GCC, say) leaves an empty OUTPUT, which models go without.
#include <cstdio>
#include <fstream>

#include "build/model_builder.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT\n", argv[0]);
    return 2;
  }
  try {
    sylva::build::precompile_runtime(argv[1], sylva::build::default_runtime_include_dir(), sylva::default_compiler());
  } catch (const sylva::ModelError& e) {
    std::fprintf(stderr, "warning: models will be compiled without a precompiled runtime header: %s\n", e.what());
    std::ofstream(argv[1], std::ios::trunc);
  }
  return 0;
}
