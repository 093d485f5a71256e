#include "build/cache_maintenance.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include "build/cache_manifest.h"
#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::build {
namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kDefaultLimit = std::uint64_t{1} << 30;
// A temporary file this old belongs to a run that was killed outright (an
// interrupted run removes its own); younger ones may be a compile going on
// (older versions of Sylva compiled from KEY.ii, and kept it).
constexpr std::chrono::hours kAbandonedAfter{1};

// A compiled model's files: KEY.so, KEY.sum, KEY.lock.
constexpr const char* kKeyFiles[] = {".so", ".sum", ".lock"};

// What the folder holds of one key.
struct Entry {
  std::uint64_t bytes = 0;
  bool has_library = false;
  std::chrono::system_clock::time_point last_used{};
};

struct Contents {
  std::map<std::string, Entry> entries;
  std::vector<fs::path> manifests;
  std::vector<fs::path> leftovers;  // abandoned temporary files, C++ older versions kept
  std::uint64_t bytes = 0;
};

std::chrono::system_clock::time_point modified(const struct stat& st) {
  return std::chrono::system_clock::time_point(std::chrono::seconds(st.st_mtim.tv_sec) +
                                               std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                                   std::chrono::nanoseconds(st.st_mtim.tv_nsec)));
}

Contents scan(const ModelCache& cache) {
  Contents contents;
  const auto abandoned = std::chrono::system_clock::now() - kAbandonedAfter;
  std::error_code ec;
  for (const fs::directory_entry& item : fs::directory_iterator(cache.dir(), ec)) {
    const std::string name = item.path().filename().string();
    struct stat st;
    if (name.size() < 33 || !is_cache_key(name.substr(0, 32)) || name[32] != '.') continue;  // not Sylva's
    if (::lstat(item.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    const std::uint64_t bytes = static_cast<std::uint64_t>(st.st_size);
    const std::string key = name.substr(0, 32), extension = name.substr(33);
    if (extension.find("tmp") != std::string::npos || extension == "ii") {
      if (modified(st) < abandoned) contents.leftovers.push_back(item.path());
    } else if (extension == "manifest") {
      contents.manifests.push_back(item.path());
    } else if (extension == "so" || extension == "sum" || extension == "lock") {
      Entry& entry = contents.entries[key];
      entry.bytes += bytes;
      if (extension == "so") {
        entry.has_library = true;
        entry.last_used = modified(st);
      }
    } else {
      continue;  // a name like ours, but not a file Sylva writes
    }
    contents.bytes += bytes;
  }
  return contents;
}

std::uint64_t file_bytes(const fs::path& path) {
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) ? static_cast<std::uint64_t>(st.st_size) : 0;
}

// The cache's size as last counted, in a file of its own (its name is not a
// key's, so counting passes it by), locked while it is read and written.
// A run that compiles adds what it wrote instead of counting every file:
// with 24 000 models in the cache (near the default limit) the count took
// 0.47 s of each compiling run. Files removed by hand make the tally too
// high, so the cache is pruned early, and the count then corrects it.
class SizeTally {
 public:
  explicit SizeTally(const ModelCache& cache)
      : fd_(::open(cache.file(kName).c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600)) {
    // Without the file (or a lock), every compile counts, as when it is new.
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) close();
  }
  ~SizeTally() { close(); }
  SizeTally(const SizeTally&) = delete;
  SizeTally& operator=(const SizeTally&) = delete;

  std::optional<std::uint64_t> bytes() const {
    char text[32] = {};
    if (fd_ < 0 || ::pread(fd_, text, sizeof text - 1, 0) <= 0 || !std::isdigit(static_cast<unsigned char>(text[0])))
      return std::nullopt;
    char* end = nullptr;
    const unsigned long long bytes = std::strtoull(text, &end, 10);
    if (end == text || *end != '\n') return std::nullopt;
    return bytes;
  }
  void set_bytes(std::uint64_t bytes) {
    if (fd_ < 0) return;
    const std::string text = std::to_string(bytes) + "\n";
    if (::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()) ||
        ::ftruncate(fd_, static_cast<off_t>(text.size())) != 0)
      (void)::ftruncate(fd_, 0);  // unreadable: the next compile counts
  }

 private:
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  static constexpr const char* kName = "cache-size";
  int fd_;
};

std::uint64_t remove_file(const fs::path& path) {
  const std::uint64_t bytes = file_bytes(path);
  return ::unlink(path.c_str()) == 0 ? bytes : 0;
}

PruneResult prune(const ModelCache& cache, std::uint64_t max_bytes, const std::string& keep, bool always_tidy) {
  Contents contents = scan(cache);
  PruneResult result;
  for (const fs::path& leftover : contents.leftovers) result.bytes_removed += remove_file(leftover);

  std::vector<std::pair<std::string, Entry>> by_age(contents.entries.begin(), contents.entries.end());
  std::stable_sort(by_age.begin(), by_age.end(), [](const auto& a, const auto& b) {
    // Files left without a library go first.
    return std::pair(a.second.has_library, a.second.last_used) < std::pair(b.second.has_library, b.second.last_used);
  });
  bool removed_library = false;
  for (const auto& [key, entry] : by_age) {
    if (contents.bytes - result.bytes_removed <= max_bytes && entry.has_library) break;
    if (key == keep) continue;
    // A library being compiled, or looked at before it is loaded, stays.
    const std::optional<ModelCache::Lock> lock = cache.try_lock(key);
    if (!lock) continue;
    for (const char* extension : kKeyFiles) result.bytes_removed += remove_file(cache.file(key + extension));
    if (entry.has_library) {
      ++result.models_removed;
      removed_library = true;
    }
  }

  // Manifests naming a library that is gone, or written by another version.
  if (removed_library || always_tidy) {
    for (const fs::path& path : contents.manifests) {
      const WholeFile text = read_whole_file(path.string());
      const std::optional<Manifest> manifest =
          text ? read_manifest(text.bytes, path.stem().string()) : std::nullopt;
      if (!manifest || !fs::exists(cache.file(manifest->library))) result.bytes_removed += remove_file(path);
    }
  }
  result.left = cache_usage(cache);
  return result;
}

}  // namespace

CacheUsage cache_usage(const ModelCache& cache) {
  const Contents contents = scan(cache);
  CacheUsage usage;
  usage.bytes = contents.bytes;
  for (const auto& [key, entry] : contents.entries) usage.models += entry.has_library ? 1 : 0;
  return usage;
}

PruneResult prune_cache(const ModelCache& cache, std::uint64_t max_bytes, const std::string& keep) {
  SizeTally tally(cache);
  const PruneResult result = prune(cache, max_bytes, keep, true);
  tally.set_bytes(result.left.bytes);
  return result;
}

void prune_cache_if_full(const ModelCache& cache, const std::string& keep, const std::string& manifest) {
  const std::uint64_t limit = cache_size_limit();
  SizeTally tally(cache);
  std::optional<std::uint64_t> bytes = tally.bytes();
  if (bytes) {
    for (const char* extension : kKeyFiles) *bytes += file_bytes(cache.file(keep + extension));
    *bytes += file_bytes(cache.file(manifest));
  } else {
    bytes = cache_usage(cache).bytes;
  }
  if (*bytes > limit) bytes = prune(cache, limit, keep, false).left.bytes;
  tally.set_bytes(*bytes);
}

PruneResult clear_cache(const ModelCache& cache) { return prune_cache(cache, 0); }

std::uint64_t cache_size_limit() {
  const char* text = std::getenv("SYLVA_CACHE_MAX_SIZE");
  if (!text || !*text) return kDefaultLimit;
  try {
    return parse_size(text);
  } catch (const std::invalid_argument& e) {
    throw ModelError(std::string("SYLVA_CACHE_MAX_SIZE: ") + e.what());
  }
}

std::uint64_t parse_size(const std::string& text) {
  const std::string expected = "expected a size such as 500M or 2G, not '" + text + "'";
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(number) || number < 0 || text[0] == '-' || text[0] == '+')
    throw std::invalid_argument(expected);
  std::string unit(end);
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (unit.ends_with("IB")) unit.resize(unit.size() - 2);
  else if (unit.size() == 2 && unit.ends_with("B")) unit.pop_back();
  static const std::string units = "KMGT";
  double multiple = 1;
  if (unit == "B") unit.clear();
  if (!unit.empty()) {
    const std::size_t power = unit.size() == 1 ? units.find(unit[0]) : std::string::npos;
    if (power == std::string::npos) throw std::invalid_argument(expected);
    multiple = std::ldexp(1.0, 10 * static_cast<int>(power + 1));
  }
  const double bytes = std::floor(number * multiple);
  if (bytes >= 0x1p63) throw std::invalid_argument(expected);
  return static_cast<std::uint64_t>(bytes);
}

std::string format_size(std::uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  double value = static_cast<double>(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 3) {
    value /= 1024;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, units[unit]);
  return text;
}

}  // namespace sylva::build
