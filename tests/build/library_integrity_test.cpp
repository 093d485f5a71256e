// A cached library is loaded only if it is the one compiled for the model,
// whole and unchanged; otherwise it is compiled again, once.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "build/cache_manifest.h"
#include "build/cache_test_support.h"
#include "build/model_library.h"
#include "support/diagnostic.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

class LibraryIntegrity : public CacheTest {
 protected:
  std::set<std::string> manifests() const {
    std::set<std::string> paths;
    for (const auto& entry : fs::directory_iterator(options_.cache_dir))
      if (entry.path().extension() == ".manifest") paths.insert(entry.path().string());
    return paths;
  }
};

// A small real model, compiled by the real compiler.
class RealLibraryIntegrity : public CacheTest {
 protected:
  RealLibraryIntegrity() {
    options_.compiler.clear();
    write("real.l", "#include <lpfgall.h>\nmodule A(int);\nderivation length: 2;\naxiom: A(0);\n"
                    "production:\nA(n) : { produce A(n + 1); }\n");
  }
  void damage(const std::string& library, std::size_t keep_bytes, bool flip) {
    std::string bytes = read_text(library);
    if (flip) bytes[bytes.size() / 2] ^= 0x5a;
    bytes.resize(std::min(keep_bytes, bytes.size()));
    // A new file in its place: the one loaded stays mapped as it was.
    std::ofstream(library + ".new", std::ios::binary) << bytes;
    fs::rename(library + ".new", library);
  }
};

TEST_F(RealLibraryIntegrity, ATruncatedLibraryIsCompiledAgainNotMapped) {
  const build::BuiltModel built = build("real.l");
  ASSERT_TRUE(built.compiled_now);
  // Power lost while the library was written: the file is shorter than its
  // headers say (mapping it would fault at the first missing page).
  damage(built.library_path, fs::file_size(built.library_path) / 2, false);
  const build::LoadedModel loaded = build::load_model(dir_ + "/real.l", options_);
  EXPECT_TRUE(loaded.built.compiled_now);
  EXPECT_EQ(loaded.built.library_path, built.library_path);
  EXPECT_EQ(loaded.library->descriptor().abi_version, abi::kAbiVersion);

  // A changed byte as well.
  damage(built.library_path, std::string::npos, true);
  const build::LoadedModel again = build::load_model(dir_ + "/real.l", options_);
  EXPECT_TRUE(again.built.compiled_now);
  EXPECT_EQ(again.library->descriptor().abi_version, abi::kAbiVersion);

  // Whole: loaded as it is.
  const build::LoadedModel cached = build::load_model(dir_ + "/real.l", options_);
  EXPECT_FALSE(cached.built.compiled_now);
}

TEST_F(LibraryIntegrity, TheChecksumIsCheckedBeforeLoading) {
  const build::BuiltModel built = build();
  std::ofstream(built.library_path, std::ios::app) << "x";
  try {
    build::ModelLibrary library(built.library_path, built.library_checksum);
    FAIL() << "loaded";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("is damaged"), std::string::npos) << e.what();
  }
}

TEST_F(LibraryIntegrity, ALibraryThatDoesNotLoadIsCompiledAgainOnceThenReported) {
  options_.compiler = stand_in("garbage", stand_in_script("echo 'not a library' > \"$out\""));
  build();  // compiled, not loaded
  try {
    build::load_model(dir_ + "/model.l", options_);
    FAIL() << "loaded";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot load compiled model"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("compiled again, once"), std::string::npos) << e.what();
  }
  EXPECT_EQ(compiles(options_.compiler).size(), 2u);

  // Compiled just now and not loadable: no second compile.
  edit("model.l", "module A(float);\naxiom: A(2);\n");
  EXPECT_THROW(build::load_model(dir_ + "/model.l", options_), ModelError);
  EXPECT_EQ(compiles(options_.compiler).size(), 3u);
}

TEST_F(LibraryIntegrity, AMissingOrDamagedChecksumMeansCompilingAgain) {
  const build::BuiltModel built = build();
  const fs::path sum = fs::path(built.library_path).replace_extension(".sum");
  fs::remove(sum);
  EXPECT_TRUE(build().compiled_now);
  std::ofstream(sum) << "0123";
  EXPECT_TRUE(build().compiled_now);
  EXPECT_FALSE(build().compiled_now);
}

TEST_F(LibraryIntegrity, AManifestNamingAnotherModelsLibraryIsNotBelieved) {
  write("other.l", "module B(float);\naxiom: B(7);\n");
  const build::BuiltModel other = build("other.l");
  ASSERT_EQ(manifests().size(), 1u);
  const std::string other_manifest = *manifests().begin();
  const build::BuiltModel model = build();
  std::set<std::string> both = manifests();
  both.erase(other_manifest);
  ASSERT_EQ(both.size(), 1u);
  const std::string model_manifest = *both.begin();
  ASSERT_NE(other.library_path, model.library_path);

  // The library line changed to the other model's library.
  std::string text = read_text(model_manifest);
  const std::string own = fs::path(model.library_path).filename().string();
  text.replace(text.find(own), own.size(), fs::path(other.library_path).filename().string());
  std::ofstream(model_manifest, std::ios::trunc) << text;
  build::BuiltModel again = build();
  EXPECT_EQ(again.library_path, model.library_path);
  EXPECT_FALSE(again.compiled_now);  // its own library is still there: translated, not compiled

  // The other model's whole manifest copied in its place.
  fs::copy_file(other_manifest, model_manifest, fs::copy_options::overwrite_existing);
  again = build();
  EXPECT_EQ(again.library_path, model.library_path);
  EXPECT_EQ(compiles(options_.compiler).size(), 2u);
}

TEST(CacheManifest, NamesOnlyALibraryInsideTheCache) {
  const std::string key(32, 'a');
  build::Manifest manifest{key, std::string(32, 'b') + ".so", {"model.l:1:1: warning: w"}, {{"1:2.3", "/m/model.l"}}};
  const std::optional<build::Manifest> read = build::read_manifest(build::manifest_text(manifest), key);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->library, manifest.library);
  EXPECT_EQ(read->warnings, manifest.warnings);
  ASSERT_EQ(read->dependencies.size(), 1u);
  EXPECT_EQ(read->dependencies[0].path, "/m/model.l");
  EXPECT_FALSE(build::read_manifest(build::manifest_text(manifest), std::string(32, 'c')));  // another lookup's

  // Whole and for this lookup, but naming a file elsewhere: not believed.
  const std::string b(32, 'b');
  for (const std::string& library :
       std::vector<std::string>{"/tmp/" + b + ".so", "../" + b + ".so", std::string(32, 'B') + ".so", b + ".so.1",
                                "lib.so", ""}) {
    manifest.library = library;
    EXPECT_FALSE(build::read_manifest(build::manifest_text(manifest), key)) << library;
  }
  // Cut short.
  manifest.library = std::string(32, 'b') + ".so";
  const std::string text = build::manifest_text(manifest);
  EXPECT_FALSE(build::read_manifest(text.substr(0, text.size() - 10), key));
  EXPECT_FALSE(build::read_manifest(text.substr(0, text.find("dep")), key));
}

}  // namespace
}  // namespace sylva::test
