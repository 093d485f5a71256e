// The cache's folder is the user's own: created private, refused if anyone
// else could put code in it, never a folder shared by every user.
#include <gtest/gtest.h>

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "build/model_builder.h"
#include "build/model_cache.h"
#include "support/diagnostic.h"
#include "build/cache_test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

std::string refusal(const std::string& dir) {
  try {
    build::ModelCache cache(dir);
  } catch (const ModelError& e) {
    return e.what();
  }
  return {};
}

TEST(CacheFolder, IsCreatedPrivate) {
  const std::string dir = make_temp_dir("cache-folder-created") + "/deeper/cache";
  build::ModelCache cache(dir);
  EXPECT_EQ(fs::status(dir).permissions() & fs::perms::all, fs::perms::owner_all);
}

TEST(CacheFolder, OneOthersCanWriteInIsRefusedWithTheFix) {
  const std::string dir = make_temp_dir("cache-folder-shared");
  for (const fs::perms shared : {fs::perms::group_write, fs::perms::others_write}) {
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | shared);
    const std::string message = refusal(dir);
    EXPECT_NE(message.find("can be written by other users"), std::string::npos) << message;
    EXPECT_NE(message.find("chmod 700 " + dir), std::string::npos) << message;
    EXPECT_NE(message.find("--cache-dir"), std::string::npos) << message;
  }
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  EXPECT_EQ(refusal(dir), "");  // readable is fine: a user's home often is
}

TEST(CacheFolder, AnotherUsersIsRefused) {
  const std::string dir = make_temp_dir("cache-folder-theirs");
  if (chown(dir.c_str(), getuid() + 1, static_cast<gid_t>(-1)) != 0) GTEST_SKIP() << "cannot give a folder away";
  const std::string message = refusal(dir);
  EXPECT_NE(message.find("belongs to another user"), std::string::npos) << message;
  EXPECT_EQ(chown(dir.c_str(), getuid(), static_cast<gid_t>(-1)), 0);
}

TEST(CacheFolder, AFileIsRefused) {
  const std::string file = write_temp_file("cache-folder-file", "cache", "");
  EXPECT_NE(refusal(file).find("is not a folder"), std::string::npos) << refusal(file);
}

TEST(CacheFolder, WithoutHomeTheUsersOwnHomeNotATemporaryFolder) {
  const ScopedVariable no_cache_dir("SYLVA_CACHE_DIR", nullptr), no_xdg("XDG_CACHE_HOME", nullptr),
      no_home("HOME", nullptr);
  const passwd* user = getpwuid(getuid());
  if (!user || !user->pw_dir || !*user->pw_dir) {
    EXPECT_THROW(build::default_cache_dir(), ModelError);
    return;
  }
  EXPECT_EQ(build::default_cache_dir(), std::string(user->pw_dir) + "/.cache/sylva");
}

TEST(CacheFolder, TheEnvironmentChoosesIt) {
  const ScopedVariable home("HOME", "/home/someone"), xdg("XDG_CACHE_HOME", "/var/cache/someone");
  {
    const ScopedVariable cache_dir("SYLVA_CACHE_DIR", "/elsewhere/cache");
    EXPECT_EQ(build::default_cache_dir(), "/elsewhere/cache");
  }
  const ScopedVariable no_cache_dir("SYLVA_CACHE_DIR", nullptr);
  EXPECT_EQ(build::default_cache_dir(), "/var/cache/someone/sylva");
  const ScopedVariable relative_xdg("XDG_CACHE_HOME", "relative");  // not absolute: ignored, as the XDG rules say
  EXPECT_EQ(build::default_cache_dir(), "/home/someone/.cache/sylva");
}

}  // namespace
}  // namespace sylva::test
