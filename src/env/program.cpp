#include "env/program.h"

namespace sylva::env {

std::vector<std::string> ProgramInvocation::positional_arguments() const {
  std::vector<std::string> positional;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& word = arguments[i];
    if (word == "-e") {  // "-e commfile.e": the communication file, read by the modeling side
      ++i;
      continue;
    }
    if (word.size() > 1 && word[0] == '-') continue;
    positional.push_back(word);
  }
  return positional;
}

std::filesystem::path ProgramInvocation::resolve(const std::string& argument) const {
  std::filesystem::path path(argument);
  return path.is_absolute() ? path : directory / path;
}

}  // namespace sylva::env
