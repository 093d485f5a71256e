// An environmental program run as a separate process, spoken to over a pair
// of pipes with the line protocol of docs/environment.md (what the sylva_comm
// library, comm_lib.h, speaks on the program's side).
#pragma once

#include <memory>
#include <string>

#include "env/comm_spec.h"
#include "env/field.h"
#include "env/program.h"

namespace sylva::env {

// The first line the engine sends; a program that speaks another version of
// the protocol says so and exits.
inline constexpr const char* kProtocolGreeting = "sylva-environment 1";

class ExternalProgramField : public Field {
 public:
  // Starts `executable` (a path to a program file) with the invocation's
  // arguments in the invocation's directory and waits for its "ready".
  // Throws ModelError at the .e file's executable: line if it cannot be
  // started, dies or does not answer within `timeout_seconds`.
  ExternalProgramField(const std::string& executable, const ProgramInvocation& invocation, const CommSpec& spec,
                       double timeout_seconds);
  ~ExternalProgramField() override;

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override;
  // Sends "exit" and waits for the program to end (killing it past the timeout).
  void finish() override;

  // The text of one pass as sent to the program (begin ... end), for tests
  // and the protocol's documentation.
  static std::string encode_pass(std::span<const Query> queries, const CommSpec& spec, int step);

 private:
  struct Process;
  std::unique_ptr<Process> process_;
};

}  // namespace sylva::env
