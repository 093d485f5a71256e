#include "support/whole_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/interruption.h"

namespace sylva {

WholeFile read_whole_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {"", WholeFile::Failure::IsFolder};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {"", WholeFile::Failure::CannotOpen};
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) return {"", WholeFile::Failure::CannotRead};
  return {text.str(), WholeFile::Failure::None};
}

int write_file_atomically(const std::string& path, std::string_view content) {
  return write_file_atomically(path, [content](const ContentSink& sink) { sink(content); });
}

int write_file_atomically(const std::string& path, const ContentProducer& produce) {
  const std::string tmp = path + ".tmp" + std::to_string(getpid());
  const interruption::TemporaryFile registered(tmp);
  // A file replaced keeps its permissions; a new one gets the umask's. The
  // temporary file has them from the start, so its content is never readable
  // by more people than the file's.
  struct stat old {};
  const bool replacing = ::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);
  const mode_t mode = replacing ? old.st_mode & 0777 : 0666;
  ::unlink(tmp.c_str());  // left by an earlier process of the same id
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
  if (fd < 0) return errno;
  int error = 0;
  if (replacing && ::fchmod(fd, mode) != 0) error = errno;  // what the umask took away
  auto write_piece = [&](std::string_view piece) {
    for (std::size_t done = 0; error == 0 && done < piece.size();) {
      const ssize_t n = ::write(fd, piece.data() + done, piece.size() - done);
      if (n >= 0) done += static_cast<std::size_t>(n);
      else if (errno != EINTR) error = errno;
    }
  };
  try {
    produce(write_piece);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) ::unlink(tmp.c_str());
  return error;
}

}  // namespace sylva
