#include "support/diagnostic.h"

namespace sylva {

std::string ModelError::format(const SourceLocation& at, const std::string& message) {
  std::string text = at.file;
  if (at.line > 0) text.append(":").append(std::to_string(at.line));
  if (at.column > 0) text.append(":").append(std::to_string(at.column));
  text.append(": error: ").append(message);
  return text;
}

}  // namespace sylva
