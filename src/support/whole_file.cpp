#include "support/whole_file.h"

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
  const std::string tmp = path + ".tmp" + std::to_string(getpid());
  const interruption::TemporaryFile registered(tmp);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return errno;
  bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  int error = ok ? 0 : errno;
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    error = errno;
  }
  if (!ok) std::remove(tmp.c_str());
  return ok ? 0 : error;
}

}  // namespace sylva
