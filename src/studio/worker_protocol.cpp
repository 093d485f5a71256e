#include "studio/worker_protocol.h"

#include <unistd.h>

#include <cerrno>
#include <stdexcept>

namespace sylva::studio {
namespace {

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// Returns false at end of file before `size` bytes.
bool read_exactly(int fd, char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

bool write_message(int fd, const WorkerMessage& message) {
  nlohmann::json json = message.json;
  if (!message.payload.empty()) json["payload"] = message.payload.size();
  const std::string line = json.dump() + "\n";
  return write_all(fd, line.data(), line.size()) &&
         write_all(fd, message.payload.data(), message.payload.size());
}

bool read_message(int fd, WorkerMessage& message) {
  // Byte by byte up to the newline: the payload that follows must stay in
  // the pipe, and lines are short.
  std::string line;
  char c = 0;
  while (true) {
    if (!read_exactly(fd, &c, 1)) return false;
    if (c == '\n') break;
    line += c;
  }
  message.json = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (message.json.is_discarded() || !message.json.is_object())
    throw std::runtime_error("a studio worker message that is not a JSON object: " + line.substr(0, 200));
  message.payload.clear();
  if (message.json.contains("payload")) {
    const auto size = message.json["payload"].get<std::size_t>();
    message.payload.resize(size);
    if (!read_exactly(fd, message.payload.data(), size)) return false;
    message.json.erase("payload");
  }
  return true;
}

}  // namespace sylva::studio
