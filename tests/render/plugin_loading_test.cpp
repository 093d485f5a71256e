// The libraries behind images (OSMesa and LLVM, libpng, cairo, GraphicsMagick)
// are loaded only by a run that makes an image, through their plugins; a run
// that writes a string loads the C and C++ runtimes and its model alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/subprocess.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// The run's standard error with the dynamic loader's list of what it loads.
std::string loaded_libraries(const std::string& dir, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"/usr/bin/env", "-C", dir, "LD_DEBUG=libs",
                                   std::string("SYLVA_CACHE_DIR=") + SYLVA_TEST_CACHE_DIR, SYLVA_BINARY, "run"};
  argv.insert(argv.end(), args.begin(), args.end());
  const ProcessResult r = run_process(argv);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.err;
}

std::string model_dir() {
  const std::string dir = make_temp_dir("plugin-loading");
  std::ofstream(dir + "/model.l") << "#include <lpfgall.h>\nderivation length: 1;\nAxiom: F(1);\n";
  return dir;
}

TEST(PluginLoading, AStringRunLoadsNoImageLibrary) {
  const std::string loaded = loaded_libraries(model_dir(), {"model.l", "--steps", "0", "--string", "out.txt"});
  for (const char* library : {"libsylva_gl", "libOSMesa", "libLLVM", "libpng", "libcairo", "libGraphicsMagick"})
    EXPECT_EQ(loaded.find(library), std::string::npos) << library << " was loaded";
}

// Each library costs a run about half a millisecond to load (docs/performance.md).
TEST(PluginLoading, AStringRunLoadsTheRuntimesAndItsModel) {
  const std::string loaded = loaded_libraries(model_dir(), {"model.l", "--steps", "0", "--string", "out.txt"});
  std::istringstream lines(loaded);
  int libraries = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find("calling init: ");
    if (at == std::string::npos) continue;
    ++libraries;
    const std::filesystem::path path = line.substr(at + 14);
    if (path.parent_path() == std::filesystem::path(SYLVA_TEST_CACHE_DIR)) continue;  // the model
    const std::string name = path.filename().string();
    bool runtime = false;
    for (const char* prefix : {"ld-linux", "libc.so", "libm.so", "libgcc_s.so", "libstdc++.so"})
      runtime = runtime || name.rfind(prefix, 0) == 0;
    EXPECT_TRUE(runtime) << name << " was loaded";
  }
  EXPECT_GE(libraries, 3) << loaded;
}

TEST(PluginLoading, AnImageRunLoadsTheGlPluginAlone) {
  const std::string dir = model_dir();
  const std::string loaded = loaded_libraries(dir, {"model.l", "-o", "image.png", "--width", "8", "--height", "8"});
  EXPECT_NE(loaded.find("libsylva_gl.so"), std::string::npos);
  EXPECT_NE(loaded.find("libOSMesa"), std::string::npos);
  EXPECT_EQ(loaded.find("libGraphicsMagick"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/image.png"));
}

TEST(PluginLoading, APdfRunLoadsTheCairoPluginAlone) {
  const std::string dir = model_dir();
  const std::string loaded = loaded_libraries(dir, {"model.l", "-o", "drawing.pdf"});
  EXPECT_NE(loaded.find("libsylva_cairo.so"), std::string::npos);
  EXPECT_EQ(loaded.find("libOSMesa"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir + "/drawing.pdf"));
}

}  // namespace
}  // namespace sylva::test
