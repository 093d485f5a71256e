// What the fuzz targets share: the input as a file for readers that take a
// path, and the line between a clean rejection and a defect.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <set>
#include <string>

#include "support/diagnostic.h"

namespace sylva::fuzz {

// Runs `read` on one input. A ModelError is the clean answer to bad input.
// Any other exception reaches the user as "sylva: error: <what>" with no
// place in the file, which is no crash but a poor message: each kind is
// printed once, for a person to look at, and the run goes on. A crash, a
// hang or a sanitizer report stops the run (libFuzzer's part).
template <class Read>
void reading(Read&& read) {
  try {
    read();
  } catch (const ModelError&) {
  } catch (const std::exception& e) {
    static std::set<std::string> seen;
    if (seen.insert(e.what()).second) std::fprintf(stderr, "unlocated error: %s\n", e.what());
  }
}

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// The input as a file, for readers that take a path: an anonymous in-memory
// file (memfd), rewritten for each input and opened again by its
// /proc/self/fd path, so no disk is touched and nothing is left behind.
class InputFile {
 public:
  InputFile() : fd_(memfd_create("sylva-fuzz-input", 0)) {
    if (fd_ < 0) std::abort();
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // The path of a file holding exactly these bytes.
  const std::string& holding(const std::uint8_t* data, std::size_t size) {
    if (ftruncate(fd_, 0) != 0) std::abort();
    for (std::size_t done = 0; done < size;) {
      const ssize_t n = pwrite(fd_, data + done, size - done, static_cast<off_t>(done));
      if (n <= 0) std::abort();
      done += static_cast<std::size_t>(n);
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

}  // namespace sylva::fuzz
