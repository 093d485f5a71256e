// How a ModelError reads: "file:line:column: error: message", with the
// parts that are not known left out.
#include <gtest/gtest.h>

#include "support/diagnostic.h"

namespace sylva {
namespace {

TEST(ModelError, FileLineColumnThenTheMessage) {
  const ModelError e(SourceLocation{"plant.l", 12, 7}, "expected ';'");
  EXPECT_STREQ(e.what(), "plant.l:12:7: error: expected ';'");
  EXPECT_EQ(e.message(), "expected ';'");
  EXPECT_EQ(e.where().file, "plant.l");
  EXPECT_EQ(e.where().line, 12);
  EXPECT_EQ(e.where().column, 7);
}

TEST(ModelError, UnknownPartsAreLeftOut) {
  EXPECT_STREQ(ModelError(SourceLocation{"plant.l", 3, 0}, "m").what(), "plant.l:3: error: m");
  EXPECT_STREQ(ModelError(SourceLocation{"plant.l", 0, 0}, "no such file").what(), "plant.l: error: no such file");
  // Without a position the message stands alone (a compiler's, already formatted).
  const ModelError plain("plant.l:1:1: error: from g++");
  EXPECT_STREQ(plain.what(), "plant.l:1:1: error: from g++");
  EXPECT_EQ(plain.where().file, "");
  EXPECT_EQ(plain.where().line, 0);
}

TEST(ModelError, IsARuntimeError) {
  try {
    throw ModelError(SourceLocation{"a.l", 1, 2}, "x");
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "a.l:1:2: error: x");
    return;
  }
  FAIL() << "not caught as std::runtime_error";
}

}  // namespace
}  // namespace sylva
