// The compiler chosen when none is named: $SYLVA_CXX, then $CXX, then g++.
#include "support/default_compiler.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace sylva {
namespace {

// Sets an environment variable for one test and restores it after.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedVariable() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(DefaultCompiler, SylvaCxxThenCxxThenGxx) {
  {
    ScopedVariable sylva("SYLVA_CXX", "clang++-17"), cxx("CXX", "c++");
    EXPECT_EQ(default_compiler(), "clang++-17");
  }
  {
    ScopedVariable sylva("SYLVA_CXX", ""), cxx("CXX", "c++");
    EXPECT_EQ(default_compiler(), "c++");  // empty counts as unset
  }
  {
    ScopedVariable sylva("SYLVA_CXX", nullptr), cxx("CXX", nullptr);
    EXPECT_EQ(default_compiler(), "g++");
  }
}

TEST(DefaultCompiler, ANamedCompilerComesFirst) {
  ScopedVariable sylva("SYLVA_CXX", "clang++-17");
  EXPECT_EQ(compiler_or_default("g++-12"), "g++-12");
  EXPECT_EQ(compiler_or_default(""), "clang++-17");
}

}  // namespace
}  // namespace sylva
