#include "support/plugin_library.h"

#include <gtest/gtest.h>

#include <string>

#include "support/diagnostic.h"

namespace sylva {
namespace {

std::string error_of(const std::string& file, const char* symbol) {
  try {
    plugin_symbol(file, symbol, "does the test's work");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

TEST(PluginLibrary, FindsThePluginsOfTheBuildTree) {
  EXPECT_NE(plugin_symbol("libsylva_gl.so", "sylva_raster_renderer", "renders PNG images"), nullptr);
  EXPECT_NE(plugin_symbol("libsylva_cairo.so", "sylva_vector_printer", "writes PDF"), nullptr);
  EXPECT_NE(plugin_symbol("libsylva_textures.so", "sylva_texture_codec", "reads textures"), nullptr);
}

TEST(PluginLibrary, AMissingPluginIsAnErrorSayingWhatItIsForAndWhereItWasLookedFor) {
  const std::string message = error_of("libsylva_missing.so", "factory");
  EXPECT_NE(message.find("cannot open libsylva_missing.so, which does the test's work"), std::string::npos) << message;
  EXPECT_NE(message.find("not found in"), std::string::npos) << message;
  EXPECT_NE(message.find(SYLVA_PLUGIN_TEST_DIR), std::string::npos) << message;
}

TEST(PluginLibrary, APluginWithoutTheFactoryIsAnError) {
  const std::string message = error_of("libsylva_gl.so", "no_such_factory");
  EXPECT_NE(message.find("has no no_such_factory"), std::string::npos) << message;
}

}  // namespace
}  // namespace sylva
