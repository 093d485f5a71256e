// The compiled-model cache, with a stand-in compiler: preprocessing goes to
// the real g++, a compile only writes an empty library and logs it. So each
// test sees exactly when a model is compiled again, without compiling one.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "build/model_builder.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

const char* const kStandInCompiler =
    "#!/bin/sh\n"
    "case \" $* \" in *\" -E \"*) exec g++ \"$@\";; esac\n"
    "out=\n"
    "while [ $# -gt 0 ]; do if [ \"$1\" = -o ]; then out=$2; fi; shift; done\n"
    "echo \"$out\" >> \"$(dirname \"$0\")/compiles.log\"\n"
    ": > \"$out\"\n";

class ModelCache : public ::testing::Test {
 protected:
  ModelCache() : dir_(make_temp_dir(std::string("cache-") + current_test())) {
    options_.compiler = stand_in("cc1");
    options_.cache_dir = dir_ + "/cache";
    write("model.l", "#include \"step.h\"\nmodule A(float);\naxiom: A(STEP);\n");
    write("step.h", "#define STEP 1\n");
  }

  static std::string current_test() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

  // A copy of the stand-in compiler in a folder of its own (its log beside it).
  std::string stand_in(const std::string& name, const char* script = kStandInCompiler) {
    fs::create_directories(dir_ + "/" + name);
    const std::string path = dir_ + "/" + name + "/c++";
    std::ofstream(path) << script;
    fs::permissions(path, fs::perms::owner_all);
    return path;
  }
  void write(const std::string& file, const std::string& text) { std::ofstream(dir_ + "/" + file) << text; }
  // Rewritten with another modification time, as an edit a moment later.
  void edit(const std::string& file, const std::string& text) {
    const fs::path path = dir_ + "/" + file;
    const auto before = fs::last_write_time(path);
    write(file, text);
    fs::last_write_time(path, before + std::chrono::seconds(2));
  }
  build::BuiltModel build() { return build::build_model(dir_ + "/model.l", options_); }

  // The libraries `compiler` has compiled, in order.
  std::vector<std::string> compiles(const std::string& compiler) const {
    std::vector<std::string> lines;
    std::ifstream in(fs::path(compiler).parent_path() / "compiles.log");
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  int files_ending(const std::string& suffix) const {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(options_.cache_dir))
      if (entry.path().string().ends_with(suffix)) ++n;
    return n;
  }

  std::string dir_;
  build::BuildOptions options_;
};

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
  options_.compiler = stand_in("broken",
                               "#!/bin/sh\n"
                               "case \" $* \" in *\" -E \"*) exec g++ \"$@\";; esac\n"
                               "echo 'model.l:3:8: error: no' >&2\n"
                               "exit 1\n");
  try {
    build();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "model.l:3:8: error: no");
  }
  EXPECT_EQ(files_ending(".so"), 0);
  EXPECT_EQ(files_ending(".manifest"), 0);
}

}  // namespace
}  // namespace sylva::test
