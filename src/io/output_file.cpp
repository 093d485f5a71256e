#include "io/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void cannot_write(const std::string& path, int error) {
  throw ModelError(SourceLocation{path, 0, 0}, std::string("cannot write the file: ") + std::strerror(error));
}

// Devices and pipes (/dev/null, /dev/stdout, a FIFO) are written in place:
// renaming a file over them would replace the device.
void write_in_place(const std::string& path, const ContentProducer& produce) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) cannot_write(path, errno);
  bool ok = true;
  try {
    produce([&](std::string_view piece) { ok = ok && std::fwrite(piece.data(), 1, piece.size(), f) == piece.size(); });
  } catch (...) {
    std::fclose(f);
    throw;
  }
  if (std::fclose(f) != 0 || !ok) cannot_write(path, errno);
}

// The file a chain of symbolic links ends at (`path` itself if it is no
// link): an output written through a link leaves the link in place. Only
// links of the user's own (or root's) are followed: one planted by another
// user in a shared folder must not lead the output onto the user's files.
std::string end_of_links(const std::string& path) {
  fs::path at = path;
  for (int links = 0; links < 40; ++links) {  // as many as the kernel follows
    struct stat link {};
    if (::lstat(at.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return at.string();
    if (link.st_uid != ::geteuid() && link.st_uid != 0)
      throw ModelError(SourceLocation{path, 0, 0},
                       "cannot write the file: " + at.string() + " is a symbolic link of another user's");
    std::error_code ec;
    const fs::path target = fs::read_symlink(at, ec);
    if (ec) cannot_write(path, ec.value());
    at = target.is_absolute() ? target : at.parent_path() / target;
  }
  cannot_write(path, ELOOP);
}

bool standard_output_failed = false;  // and said so

[[noreturn]] void standard_output_error(int error) {
  standard_output_failed = true;
  throw ModelError(std::string("sylva: error: cannot write to standard output: ") + std::strerror(error));
}

}  // namespace

void write_output_file(const std::string& path, const std::string& content) {
  write_output_file(path, [&content](const ContentSink& sink) { sink(content); });
}

void write_output_file(const std::string& path, const ContentProducer& produce) {
  if (path == "-") {
    produce([](std::string_view piece) {
      if (std::fwrite(piece.data(), 1, piece.size(), stdout) != piece.size()) standard_output_error(errno);
    });
    if (std::fflush(stdout) != 0) standard_output_error(errno);
    return;
  }
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)) {
    write_in_place(path, produce);
    return;
  }
  if (const int error = write_file_atomically(end_of_links(path), produce)) cannot_write(path, error);
}

void check_standard_output_at_exit() {
  std::atexit([] {
    if (standard_output_failed) return;
    const bool flushed = std::fflush(stdout) == 0;
    if (flushed && !std::ferror(stdout)) return;
    std::fprintf(stderr, "sylva: error: cannot write to standard output%s%s\n", flushed ? "" : ": ",
                 flushed ? "" : std::strerror(errno));
    std::_Exit(1);
  });
}

}  // namespace sylva::io
