// Models built into a cache of their own with stand-in compilers:
// preprocessing goes to the real g++, a compile only writes a library (empty
// unless the script says otherwise) and logs it. So each test sees exactly
// when a model is compiled again, without compiling one.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "build/model_builder.h"
#include "test_support.h"

namespace sylva::test {

// The compile's output file is $out; `library` writes the library.
inline std::string stand_in_script(const std::string& library = ": > \"$out\"") {
  return "#!/bin/sh\n"
         "case \" $* \" in *\" -E \"*) exec g++ \"$@\";; esac\n"
         "out=\n"
         "for a; do if [ \"$prev\" = -o ]; then out=$a; fi; prev=$a; done\n"
         "echo \"$out\" >> \"$(dirname \"$0\")/compiles.log\"\n" +
         library + "\n";
}

// Sets an environment variable (or unsets it) for the scope.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? setenv(name, value, 1) : unsetenv(name);
  }
  ~ScopedVariable() { old_ ? setenv(name_, old_->c_str(), 1) : unsetenv(name_); }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

class CacheTest : public ::testing::Test {
 protected:
  CacheTest() : dir_(make_temp_dir(std::string("cache-") + current_test())) {
    options_.compiler = stand_in("cc1");
    options_.cache_dir = dir_ + "/cache";
    write("model.l", "#include \"step.h\"\nmodule A(float);\naxiom: A(STEP);\n");
    write("step.h", "#define STEP 1\n");
  }

  static std::string current_test() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

  // A copy of a stand-in compiler in a folder of its own (its log beside it).
  std::string stand_in(const std::string& name, const std::string& script = stand_in_script()) {
    std::filesystem::create_directories(dir_ + "/" + name);
    const std::string path = dir_ + "/" + name + "/c++";
    std::ofstream(path) << script;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path;
  }
  void write(const std::string& file, const std::string& text) { std::ofstream(dir_ + "/" + file) << text; }
  // Rewritten with another modification time, as an edit a moment later.
  void edit(const std::string& file, const std::string& text) {
    const std::filesystem::path path = dir_ + "/" + file;
    const auto before = std::filesystem::last_write_time(path);
    write(file, text);
    std::filesystem::last_write_time(path, before + std::chrono::seconds(2));
  }
  build::BuiltModel build(const std::string& model = "model.l") {
    return build::build_model(dir_ + "/" + model, options_);
  }

  // The libraries `compiler` has compiled, in order.
  std::vector<std::string> compiles(const std::string& compiler) const {
    std::vector<std::string> lines;
    std::ifstream in(std::filesystem::path(compiler).parent_path() / "compiles.log");
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  // Files in `dir` (the cache by default) whose name ends with, or contains, `part`.
  int files_ending(const std::string& suffix, std::string dir = {}) const {
    return count_files(dir, [&](const std::string& name) { return name.ends_with(suffix); });
  }
  int files_containing(const std::string& part, std::string dir = {}) const {
    return count_files(dir, [&](const std::string& name) { return name.find(part) != std::string::npos; });
  }

  std::string dir_;
  build::BuildOptions options_;

 private:
  template <class Test>
  int count_files(const std::string& dir, Test test) const {
    int n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.empty() ? options_.cache_dir : dir))
      if (test(entry.path().filename().string())) ++n;
    return n;
  }
};

}  // namespace sylva::test
