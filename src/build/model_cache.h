// The folder compiled models are kept in. Nothing in it is believed without a
// check: the folder must be private to the user, a library is loaded only
// from inside it and only if its bytes match the checksum recorded when it
// was compiled, and every file appears whole (written, flushed to the disk,
// then renamed into place).
//
// Layout: KEY.so a compiled model (KEY: the content key of its C++, 32 hex
// digits), KEY.sum its checksum, KEY.lock locked while KEY is compiled;
// LOOKUP.manifest (build/cache_manifest.h) for each way a model was run;
// cache-size the folder's size as last counted (build/cache_maintenance.h).
// A library's modification time is its last use.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace sylva::build {

// Bumped whenever the layout, generated code or the runtime's contract changes.
inline constexpr const char* kCacheFormat = "sylva-model-cache-20";

class ModelCache {
 public:
  // Creates the folder private to the user (0700), or checks that an existing
  // one belongs to the user and that no one else can write in it; throws
  // ModelError saying how to put it right otherwise.
  explicit ModelCache(std::filesystem::path dir);

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path file(const std::string& name) const { return dir_ / name; }
  std::filesystem::path library(const std::string& key) const { return dir_ / (key + ".so"); }

  // Held while a key's library is looked at and compiled: concurrent runs of
  // one model compile it once, the others wait and take it.
  class Lock {
   public:
    Lock() = default;
    explicit Lock(int fd) : fd_(fd) {}
    Lock(Lock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    Lock& operator=(Lock&&) = delete;
    ~Lock();

   private:
    int fd_ = -1;
  };
  // Waits for the lock; `on_wait` is called first if another run holds it.
  Lock lock(const std::string& key, void (*on_wait)() = nullptr) const;
  // The lock if no one holds it.
  std::optional<Lock> try_lock(const std::string& key) const;

  // The checksum recorded for KEY's library, if both are there.
  std::optional<std::string> recorded_checksum(const std::string& key) const;
  // The recorded checksum, if the library's bytes match it.
  std::optional<std::string> verified_checksum(const std::string& key) const;

  // Makes `compiled` (the compiler's output, beside the library) KEY's
  // library: flushed to the disk, its checksum recorded, renamed into place.
  // Returns the checksum. Call with KEY locked.
  std::string install_library(const std::filesystem::path& compiled, const std::string& key) const;
  // Removes KEY's library and checksum (a library that would not load).
  void discard_library(const std::string& key) const;
  // Marks KEY's library used now: pruning removes the least recently used.
  void mark_used(const std::string& key) const;

  // Written to a temporary file, flushed to the disk and renamed over NAME.
  void write_file(const std::string& name, std::string_view content) const;

 private:
  std::filesystem::path dir_;
};

// A library's checksum: the content hash of its bytes.
std::string library_checksum(std::string_view bytes);

// The library file's checksum, or nothing if it cannot be read whole.
std::optional<std::string> file_checksum(const std::filesystem::path& path);

// PATH.tmpPID (PATH.tmpPID-TID off the main thread): unique among the runs
// and threads writing beside PATH at once.
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace sylva::build
