#include "io/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::io {

namespace {

// Devices and pipes (/dev/null, /dev/stdout, a FIFO) are written in place:
// renaming a file over them would replace the device.
void write_in_place(const std::string& path, const std::string& content) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw ModelError(SourceLocation{path, 0, 0}, std::string("cannot write the file: ") + std::strerror(errno));
  bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  if (std::fclose(f) != 0 || !ok)
    throw ModelError(SourceLocation{path, 0, 0}, std::string("cannot write the file: ") + std::strerror(errno));
}

}  // namespace

void write_output_file(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::fwrite(content.data(), 1, content.size(), stdout);
    std::fflush(stdout);
    return;
  }
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
      !std::filesystem::is_directory(status)) {
    write_in_place(path, content);
    return;
  }
  if (const int error = write_file_atomically(path, content))
    throw ModelError(SourceLocation{path, 0, 0}, std::string("cannot write the file: ") + std::strerror(error));
}

}  // namespace sylva::io
