// The studio's server and its worker processes talk over a pair of pipes in
// messages: one line of JSON, then `payload` raw bytes when the JSON has a
// "payload" field giving their number (a glTF scene, an exported file). The
// server writes requests to the worker's standard input and reads answers
// from its standard output; the worker's standard error is left for the
// model's own printing.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace sylva::studio {

struct WorkerMessage {
  nlohmann::json json;
  std::string payload;
};

// Both return false when the other end is gone (end of file, a broken pipe)
// and throw std::runtime_error for a message that is not well formed.
bool write_message(int fd, const WorkerMessage& message);
bool read_message(int fd, WorkerMessage& message);

}  // namespace sylva::studio
