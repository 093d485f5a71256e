// The compiled-model cache, with a stand-in compiler (cache_test_support.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "build/cache_test_support.h"
#include "build/model_builder.h"
#include "support/diagnostic.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

class ModelCache : public CacheTest {};

TEST_F(ModelCache, AnUnchangedModelIsNotCompiledAgain) {
  const build::BuiltModel first = build();
  EXPECT_TRUE(first.compiled_now);
  EXPECT_TRUE(fs::exists(first.library_path));
  EXPECT_EQ(fs::path(first.library_path).parent_path(), fs::path(options_.cache_dir));
  const build::BuiltModel again = build();
  EXPECT_FALSE(again.compiled_now);
  EXPECT_EQ(again.library_path, first.library_path);
  EXPECT_EQ(compiles(options_.compiler), std::vector<std::string>{first.library_path + ".tmp" + std::to_string(getpid())});
}

TEST_F(ModelCache, AChangedModelOrIncludedFileIsCompiledAgain) {
  const build::BuiltModel first = build();
  edit("model.l", "#include \"step.h\"\nmodule A(float);\naxiom: A(STEP + 1);\n");
  const build::BuiltModel changed = build();
  EXPECT_TRUE(changed.compiled_now);
  EXPECT_NE(changed.library_path, first.library_path);

  edit("step.h", "#define STEP 2\n");
  const build::BuiltModel header_changed = build();
  EXPECT_TRUE(header_changed.compiled_now);
  EXPECT_NE(header_changed.library_path, changed.library_path);
  EXPECT_EQ(compiles(options_.compiler).size(), 3u);

  // Back to the first text: its library is still in the cache.
  edit("step.h", "#define STEP 1\n");
  edit("model.l", "#include \"step.h\"\nmodule A(float);\naxiom: A(STEP);\n");
  const build::BuiltModel back = build();
  EXPECT_FALSE(back.compiled_now);
  EXPECT_EQ(back.library_path, first.library_path);
  EXPECT_EQ(compiles(options_.compiler).size(), 3u);
}

TEST_F(ModelCache, DefinesArePartOfTheKey) {
  build();
  EXPECT_EQ(files_ending(".manifest"), 1);
  // A define the model reads: other C++, another library.
  options_.defines = {"STEP_OVERRIDE=1"};
  edit("model.l", "#include \"step.h\"\n#ifdef STEP_OVERRIDE\n#undef STEP\n#define STEP 9\n#endif\n"
                  "module A(float);\naxiom: A(STEP);\n");
  const build::BuiltModel defined = build();
  EXPECT_TRUE(defined.compiled_now);
  options_.defines = {};
  const build::BuiltModel undefined = build();
  EXPECT_TRUE(undefined.compiled_now);
  EXPECT_NE(defined.library_path, undefined.library_path);
  // A define the model never reads: a lookup of its own, but the same C++, so the same library.
  options_.defines = {"UNUSED=1"};
  const int manifests = files_ending(".manifest");
  const build::BuiltModel unused = build();
  EXPECT_FALSE(unused.compiled_now);
  EXPECT_EQ(unused.library_path, undefined.library_path);
  EXPECT_EQ(files_ending(".manifest"), manifests + 1);
  EXPECT_EQ(compiles(options_.compiler).size(), 3u);
}

TEST_F(ModelCache, AnotherCompilerCompilesAgain) {
  const build::BuiltModel first = build();
  const std::string first_compiler = options_.compiler;
  options_.compiler = stand_in("cc2");
  const build::BuiltModel second = build();
  EXPECT_TRUE(second.compiled_now);
  EXPECT_NE(second.library_path, first.library_path);
  EXPECT_EQ(compiles(first_compiler).size(), 1u);
  EXPECT_EQ(compiles(options_.compiler).size(), 1u);
}

TEST_F(ModelCache, TheTranslatorsWarningsComeBackFromTheCache) {
  write("plant.l", "Lsystem: 1\naxiom: A\nA --> B : 0.3\nendlsystem\n");
  const std::string model = dir_ + "/plant.l";
  const std::vector<std::string> expected = {
      model + ":3:11: warning: probability ignored: the L-system has no seed:, so its productions are not chosen at "
              "random"};
  const build::BuiltModel first = build::build_model(model, options_);
  EXPECT_TRUE(first.compiled_now);
  EXPECT_EQ(first.warnings, expected);
  const build::BuiltModel cached = build::build_model(model, options_);
  EXPECT_FALSE(cached.compiled_now);
  EXPECT_EQ(cached.warnings, expected);
}

TEST_F(ModelCache, AFailedCompileLeavesNoLibrary) {
  // It preprocesses, then every compile fails with a message about the model.
  options_.compiler = stand_in("broken", stand_in_script(": > \"$out\"; echo 'model.l:3:8: error: no' >&2; exit 1"));
  try {
    build();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "model.l:3:8: error: no");
  }
  EXPECT_EQ(files_ending(".so"), 0);
  EXPECT_EQ(files_ending(".manifest"), 0);
  // Nor its C++, nor the compiler's partial output.
  EXPECT_EQ(files_ending(".ii"), 0);
  EXPECT_EQ(files_containing(".tmp"), 0);
  EXPECT_EQ(compiles(options_.compiler).size(), 1u);
}

TEST_F(ModelCache, ACompileKeepsOnlyTheLibrary) {
  const build::BuiltModel built = build();
  EXPECT_EQ(files_ending(".ii"), 0);
  EXPECT_EQ(files_containing(".tmp"), 0);
  EXPECT_EQ(files_ending(".so"), 1);
  EXPECT_EQ(files_ending(".sum"), 1);
  EXPECT_EQ(files_ending(".manifest"), 1);
  EXPECT_EQ(fs::status(options_.cache_dir).permissions() & fs::perms::all, fs::perms::owner_all);
}

}  // namespace
}  // namespace sylva::test
