// Errors that point into the user's model: file, line, column and what was
// expected. Every layer throws ModelError; the front doors print it.
#pragma once

#include <stdexcept>
#include <string>

namespace sylva {

struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

class ModelError : public std::runtime_error {
 public:
  ModelError(SourceLocation where, const std::string& message)
      : std::runtime_error(format(where, message)), where_(std::move(where)), message_(message) {}

  // An error with no position (a compiler failure already printed in full).
  explicit ModelError(const std::string& message) : std::runtime_error(message), message_(message) {}

  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const SourceLocation& at, const std::string& message);
  SourceLocation where_;
  std::string message_;
};

}  // namespace sylva
