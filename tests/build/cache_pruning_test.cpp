// The cache is kept to a size: least recently used models go first.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "build/cache_maintenance.h"
#include "build/cache_test_support.h"
#include "build/model_cache.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

constexpr std::uint64_t kLibraryBytes = 100 * 1024;
// A manifest lists every header the model read (about 16 KiB here).
constexpr std::uint64_t kRoomForManifests = 64 * 1024;

class CachePruning : public CacheTest {
 protected:
  CachePruning() {
    options_.compiler = stand_in("big", stand_in_script("head -c 102400 /dev/zero > \"$out\""));
    for (const char* name : {"a", "b", "c"})
      write(std::string(name) + ".l", "module " + std::string(name) + "(float);\naxiom: " + name + "(1);\n");
  }
  // Builds the model and dates its last use `minutes_ago`.
  build::BuiltModel build_used(const std::string& model, int minutes_ago) {
    build::BuiltModel built = build(model);
    fs::last_write_time(built.library_path, fs::file_time_type::clock::now() - std::chrono::minutes(minutes_ago));
    return built;
  }
  build::ModelCache cache() const { return build::ModelCache(options_.cache_dir); }
  // The size of the cache as last counted, as runs keep it.
  std::string tally() const { return read_text(options_.cache_dir + "/cache-size"); }
  void set_tally(const std::string& text) { std::ofstream(options_.cache_dir + "/cache-size") << text; }
};

TEST_F(CachePruning, TheLeastRecentlyUsedGoFirst) {
  const build::BuiltModel a = build_used("a.l", 30), b = build_used("b.l", 10), c = build_used("c.l", 20);
  EXPECT_EQ(build::cache_usage(cache()).models, 3);
  EXPECT_GE(build::cache_usage(cache()).bytes, 3 * kLibraryBytes);

  // Taking `a` from the cache makes it the most recently used.
  EXPECT_FALSE(build("a.l").compiled_now);
  const build::PruneResult result = build::prune_cache(cache(), 2 * kLibraryBytes + kRoomForManifests);
  EXPECT_EQ(result.models_removed, 1);
  EXPECT_GE(result.bytes_removed, kLibraryBytes);
  EXPECT_EQ(result.left.models, 2);
  EXPECT_FALSE(fs::exists(c.library_path));
  EXPECT_TRUE(fs::exists(a.library_path));
  EXPECT_TRUE(fs::exists(b.library_path));
  EXPECT_EQ(files_ending(".manifest"), 2);  // c's went with its library
  EXPECT_EQ(files_ending(".sum"), 2);
  EXPECT_EQ(compiles(options_.compiler).size(), 3u);
  EXPECT_TRUE(build("c.l").compiled_now);
}

TEST_F(CachePruning, AModelBeingCompiledStays) {
  const build::BuiltModel a = build_used("a.l", 30);
  const std::string key = fs::path(a.library_path).stem().string();
  {
    const build::ModelCache::Lock compiling = cache().lock(key);
    EXPECT_EQ(build::prune_cache(cache(), 0).models_removed, 0);
  }
  EXPECT_EQ(build::prune_cache(cache(), 0, key).models_removed, 0);  // the one just built
  EXPECT_EQ(build::prune_cache(cache(), 0).models_removed, 1);
  EXPECT_EQ(build::cache_usage(cache()).models, 0);
}

TEST_F(CachePruning, RunsPruneAfterCompilingPastTheLimit) {
  const ScopedVariable limit("SYLVA_CACHE_MAX_SIZE", "300K");
  const build::BuiltModel a = build_used("a.l", 30), b = build_used("b.l", 20);
  const build::BuiltModel c = build("c.l");
  EXPECT_FALSE(fs::exists(a.library_path));
  EXPECT_TRUE(fs::exists(b.library_path));
  EXPECT_TRUE(fs::exists(c.library_path));
}

TEST_F(CachePruning, RunsAddWhatTheyCompiledToTheSizeLastCounted) {
  const ScopedVariable limit("SYLVA_CACHE_MAX_SIZE", "300K");
  const build::BuiltModel a = build_used("a.l", 30);
  // The first compile counts the cache.
  EXPECT_EQ(tally(), std::to_string(build::cache_usage(cache()).bytes) + "\n");
  // Told the cache is empty, runs believe it: two more libraries make
  // 300 KiB and a little more in the folder, but the tally reads less than
  // 300 KiB and nothing goes.
  set_tally("0\n");
  const std::uint64_t before_b = build::cache_usage(cache()).bytes;
  const build::BuiltModel b = build_used("b.l", 20);
  // What b's compile wrote: library, checksum, lock and manifest.
  const std::uint64_t b_wrote = build::cache_usage(cache()).bytes - before_b;
  EXPECT_GE(b_wrote, kLibraryBytes);
  EXPECT_EQ(tally(), std::to_string(b_wrote) + "\n");
  const build::BuiltModel c = build_used("c.l", 10);
  EXPECT_EQ(tally(), std::to_string(build::cache_usage(cache()).bytes - before_b) + "\n");
  EXPECT_TRUE(fs::exists(a.library_path));
  EXPECT_GT(build::cache_usage(cache()).bytes, 300u << 10);
  // A fourth takes the tally past the limit: the cache is counted, the least
  // recently used go, and the tally is the count of what is left.
  write("d.l", "module d(float);\naxiom: d(1);\n");
  build("d.l");
  EXPECT_FALSE(fs::exists(a.library_path));
  EXPECT_FALSE(fs::exists(b.library_path));
  EXPECT_TRUE(fs::exists(c.library_path));
  EXPECT_EQ(tally(), std::to_string(build::cache_usage(cache()).bytes) + "\n");
}

TEST_F(CachePruning, RunsCompilingAtOnceEachAddTheirShare) {
  build("a.l");  // the first compile counts
  options_.compiler = stand_in("big_slow", stand_in_script("sleep 0.3; head -c 102400 /dev/zero > \"$out\""));
  std::vector<std::thread> runs;
  for (const char* name : {"b", "c", "d", "e"}) {
    write(std::string(name) + "2.l", "module " + std::string(name) + "(float);\naxiom: " + name + "(2);\n");
    runs.emplace_back([this, name] { build(std::string(name) + "2.l"); });
  }
  for (std::thread& run : runs) run.join();
  EXPECT_EQ(build::cache_usage(cache()).models, 5);
  EXPECT_EQ(tally(), std::to_string(build::cache_usage(cache()).bytes) + "\n");
}

TEST_F(CachePruning, AnUnreadableTallyIsCountedAgain) {
  build("a.l");
  int step = 1;
  for (const char* text : {"", "lots\n", "12", "-5\n", " 7\n"}) {
    set_tally(text);
    edit("step.h", "#define STEP " + std::to_string(++step) + "\n");
    EXPECT_TRUE(build().compiled_now);
    EXPECT_EQ(tally(), std::to_string(build::cache_usage(cache()).bytes) + "\n") << "'" << text << "'";
  }
}

TEST_F(CachePruning, ClearRemovesEveryModelAndOnlySylvasFiles) {
  build("a.l");
  build("b.l");
  std::ofstream(options_.cache_dir + "/notes.txt") << "mine";
  // Left by a run killed outright long ago, and the C++ older versions kept.
  const std::string key(32, 'e');
  std::ofstream(options_.cache_dir + "/" + key + ".so.tmp123") << "partial";
  fs::last_write_time(options_.cache_dir + "/" + key + ".so.tmp123",
                      fs::file_time_type::clock::now() - std::chrono::hours(2));
  std::ofstream(options_.cache_dir + "/" + key + ".ii") << "int x;";
  fs::last_write_time(options_.cache_dir + "/" + key + ".ii", fs::file_time_type::clock::now() - std::chrono::hours(2));
  const build::PruneResult result = build::clear_cache(cache());
  EXPECT_EQ(result.models_removed, 2);
  EXPECT_EQ(result.left.models, 0);
  EXPECT_EQ(result.left.bytes, 0u);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(options_.cache_dir)) left.push_back(entry.path().filename());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"cache-size", "notes.txt"}));
  EXPECT_EQ(tally(), "0\n");
}

TEST(CacheSizes, ReadAndWritten) {
  EXPECT_EQ(build::parse_size("4096"), 4096u);
  EXPECT_EQ(build::parse_size("500M"), 500u << 20);
  EXPECT_EQ(build::parse_size("2G"), std::uint64_t{2} << 30);
  EXPECT_EQ(build::parse_size("1.5GiB"), std::uint64_t{3} << 29);
  EXPECT_EQ(build::parse_size("10kb"), 10u << 10);
  EXPECT_EQ(build::parse_size("0"), 0u);
  for (const char* bad : {"", "G", "-1G", "12X", "1GG", "nan", "inf", "1e30"})
    EXPECT_THROW(build::parse_size(bad), std::invalid_argument) << bad;
  EXPECT_EQ(build::format_size(512), "512 bytes");
  EXPECT_EQ(build::format_size(1536), "1.5 KiB");
  EXPECT_EQ(build::format_size(std::uint64_t{1} << 30), "1.0 GiB");
  EXPECT_EQ(build::format_size(std::uint64_t{300} << 20), "300 MiB");
}

}  // namespace
}  // namespace sylva::test
