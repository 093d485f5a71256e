#include "build/model_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "build/cache_manifest.h"
#include "support/content_hash.h"
#include "support/diagnostic.h"
#include "support/interruption.h"

namespace sylva::build {
namespace fs = std::filesystem;

namespace {

const char* const kChooseAnother = "choose another folder with --cache-dir or SYLVA_CACHE_DIR";

std::string error_text(int error) { return std::strerror(error); }

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Read into one buffer of the file's size: growing a string chunk by chunk
// costs more than hashing what it holds.
std::optional<std::string> read_all(int fd) {
  struct stat st;
  if (::fstat(fd, &st) != 0) return std::nullopt;
  std::string bytes(static_cast<std::size_t>(std::max<off_t>(st.st_size, 0)) + 1, '\0');
  std::size_t size = 0;
  for (;;) {
    if (size == bytes.size()) bytes.resize(bytes.size() * 2);  // it grew meanwhile
    const ssize_t n = ::read(fd, bytes.data() + size, bytes.size() - size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) break;
    size += static_cast<std::size_t>(n);
  }
  bytes.resize(size);
  return bytes;
}

// A rename is on the disk once the folder holding it is.
void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

bool same_file(int fd, const fs::path& path) {
  struct stat held, current;
  return ::fstat(fd, &held) == 0 && ::stat(path.c_str(), &current) == 0 && held.st_dev == current.st_dev &&
         held.st_ino == current.st_ino;
}

}  // namespace

ModelCache::ModelCache(fs::path dir) : dir_(std::move(dir)) {
  const std::string name = dir_.string();
  struct stat st;
  if (::stat(dir_.c_str(), &st) != 0) {
    std::error_code ignored;
    if (dir_.has_parent_path()) fs::create_directories(dir_.parent_path(), ignored);
    if (::mkdir(dir_.c_str(), 0700) != 0 && errno != EEXIST)
      throw ModelError("cannot create the model cache " + name + ": " + error_text(errno));
    if (::stat(dir_.c_str(), &st) != 0)
      throw ModelError("cannot use the model cache " + name + ": " + error_text(errno));
  }
  // Sylva runs the code it finds in here: no one but the user may put any there.
  if (!S_ISDIR(st.st_mode)) throw ModelError("the model cache " + name + " is not a folder: " + kChooseAnother);
  if (st.st_uid != ::geteuid())
    throw ModelError("the model cache " + name + " belongs to another user (uid " + std::to_string(st.st_uid) +
                     "), and Sylva runs the code kept there: " + kChooseAnother);
  if (st.st_mode & (S_IWGRP | S_IWOTH)) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw ModelError("the model cache " + name + " can be written by other users (mode " + mode +
                     "), and Sylva runs the code kept there: make it private with `chmod 700 " + name + "`, or " +
                     kChooseAnother);
  }
}

ModelCache::Lock::~Lock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

ModelCache::Lock ModelCache::lock(const std::string& key, void (*on_wait)()) const {
  const fs::path path = file(key + ".lock");
  for (bool told = false;;) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    // Without a lock (a file system that has none) runs only compile twice.
    if (fd < 0) return Lock();
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      if (errno != EWOULDBLOCK) return Lock(fd);
      if (on_wait && !told) on_wait();
      told = true;
      while (::flock(fd, LOCK_EX) != 0)
        if (errno != EINTR) return Lock(fd);
    }
    // Pruning removes a lock file with its library: a lock on a removed file
    // would keep no one out, so take the one now there.
    if (same_file(fd, path)) return Lock(fd);
    ::close(fd);
  }
}

std::optional<ModelCache::Lock> ModelCache::try_lock(const std::string& key) const {
  const fs::path path = file(key + ".lock");
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  if (fd < 0) return std::nullopt;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 || !same_file(fd, path)) {
    ::close(fd);
    return std::nullopt;
  }
  return Lock(fd);
}

std::optional<std::string> ModelCache::recorded_checksum(const std::string& key) const {
  const int fd = ::open(file(key + ".sum").c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return std::nullopt;
  std::optional<std::string> text = read_all(fd);
  ::close(fd);
  if (!text || text->size() != 33 || text->back() != '\n') return std::nullopt;
  text->pop_back();
  if (!is_cache_key(*text)) return std::nullopt;
  struct stat st;
  if (::lstat(library(key).c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return text;
}

std::optional<std::string> ModelCache::verified_checksum(const std::string& key) const {
  std::optional<std::string> recorded = recorded_checksum(key);
  if (recorded && file_checksum(library(key)) == recorded) return recorded;
  return std::nullopt;
}

std::string ModelCache::install_library(const fs::path& compiled, const std::string& key) const {
  const int fd = ::open(compiled.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw ModelError("cannot read the compiled model " + compiled.string() + ": " + error_text(errno));
  const std::optional<std::string> bytes = read_all(fd);
  const bool synced = ::fsync(fd) == 0;
  const int error = errno;
  ::close(fd);
  if (!bytes || !synced)
    throw ModelError("cannot write the compiled model " + compiled.string() + ": " + error_text(error));
  const std::string checksum = library_checksum(*bytes);
  write_file(key + ".sum", checksum + "\n");
  if (::rename(compiled.c_str(), library(key).c_str()) != 0)
    throw ModelError("cannot write the compiled model " + library(key).string() + ": " + error_text(errno));
  sync_folder(dir_);
  return checksum;
}

void ModelCache::discard_library(const std::string& key) const {
  ::unlink(library(key).c_str());
  ::unlink(file(key + ".sum").c_str());
}

void ModelCache::mark_used(const std::string& key) const {
  ::utimensat(AT_FDCWD, library(key).c_str(), nullptr, 0);
}

void ModelCache::write_file(const std::string& name, std::string_view content) const {
  const fs::path path = file(name);
  const fs::path tmp = temporary_path(path);
  const interruption::TemporaryFile registered(tmp.string());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) throw ModelError("cannot write " + tmp.string() + ": " + error_text(errno));
  bool ok = write_all(fd, content) && ::fsync(fd) == 0;
  int error = errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (ok && ::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    error = errno;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    throw ModelError("cannot write " + path.string() + ": " + error_text(error));
  }
  sync_folder(dir_);
}

std::string library_checksum(std::string_view bytes) {
  ContentHash h;
  h.add(bytes);
  return h.hex();
}

std::optional<std::string> file_checksum(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return std::nullopt;
  struct stat st;
  std::optional<std::string> bytes;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) bytes = read_all(fd);
  ::close(fd);
  if (!bytes) return std::nullopt;
  return library_checksum(*bytes);
}

fs::path temporary_path(const fs::path& path) {
  const pid_t pid = ::getpid(), thread = ::gettid();
  std::string suffix = ".tmp" + std::to_string(pid);
  if (thread != pid) suffix += "-" + std::to_string(thread);
  fs::path tmp = path;
  tmp += suffix;
  return tmp;
}

}  // namespace sylva::build
