// Where the decoders send commands: the dispatcher executes each as it is
// decoded, one module at a time, the command never stored (a decoder calls
// the runner with the command's own type, so nothing is looked up twice).
// When a trace is wanted the runner keeps the last command and what it did,
// for the trace to tell.
#pragma once

#include <type_traits>

#include "turtle/command.h"
#include "turtle/dispatcher.h"

namespace sylva::turtle {

class CommandRunner {
 public:
  CommandRunner(CommandDispatcher& turtle, bool keeps_last) : turtle_(turtle), keeps_last_(keeps_last) {}

  template <class Command>
  void operator()(const Command& command) {
    if constexpr (std::is_void_v<decltype(turtle_.run(command))>) {
      turtle_.run(command);
      if (!keeps_last_) return;
      result_ = CommandResult{};
    } else {
      const CommandResult result = turtle_.run(command);
      if (!keeps_last_) return;
      result_ = result;
    }
    last_ = command;
  }

  // The last command and what it did (kept only when asked for).
  const TurtleCommand& last() const { return last_; }
  const CommandResult& result() const { return result_; }

 private:
  CommandDispatcher& turtle_;
  bool keeps_last_;
  TurtleCommand last_;
  CommandResult result_;
};

}  // namespace sylva::turtle
