// Building blocks for the collision programs' tests: a parameter file in a
// fresh folder, the invocation that names it, and queries made by hand.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "env/field.h"
#include "env/program.h"
#include "test_support.h"

namespace sylva::env::test {

// Writes `files` (name, content) into a fresh folder and returns the
// invocation "program [-e x.e] <first file>" run from that folder.
inline ProgramInvocation invocation_with(const std::string& program,
                                         const std::vector<std::pair<std::string, std::string>>& files) {
  std::filesystem::path dir = sylva::test::make_temp_dir(program + "-" + std::to_string(files.size()) + "-" +
                                                         std::to_string(std::hash<std::string>{}(files[0].second)));
  for (const auto& [name, content] : files) std::ofstream(dir / name) << content;
  ProgramInvocation invocation;
  invocation.program = program;
  invocation.arguments = {"-e", "commfile.e", files[0].first};
  invocation.directory = dir;
  invocation.e_file = (dir / "commfile.e").string();
  invocation.e_file_line = 1;
  return invocation;
}

// A communication module ?E(parameters) with the turtle at `position`
// ("turtle position: %g %g %g"), heading up the y axis.
inline Query query_at(std::array<float, 3> position, std::vector<float> parameters, std::uint64_t id = 0) {
  Query query;
  query.id = id;
  query.module = {"?E", std::move(parameters)};
  query.turtle.position = position;
  query.turtle.position_count = 3;
  query.turtle.heading = {0, 1, 0};
  query.turtle.left = {-1, 0, 0};
  query.turtle.up = {0, 0, 1};
  return query;
}

// Answers `queries` in one pass and returns the answers.
inline std::vector<Answer> answer_all(Field& field, const std::vector<Query>& queries, int step = 1) {
  std::vector<Answer> answers(queries.size());
  field.answer(queries, answers, step);
  return answers;
}

// The answered first parameter, or -1 when the program left it unset.
inline float first_answer(const Answer& answer) { return answer.set[0] ? answer.value[0] : -1.0f; }

}  // namespace sylva::env::test
