// Building the inputs of the light programs by hand: parameter files in a
// temporary folder, invocations naming them, and queries.
#pragma once

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "env/field.h"
#include "env/program.h"
#include "test_support.h"

namespace sylva::test::light {

// Writes `text` as `name` in a fresh folder for `test` and returns an
// invocation "program -e field.e name" run from that folder.
inline env::ProgramInvocation invocation_with_file(const std::string& test, const std::string& program,
                                                   const std::string& name, const std::string& text) {
  std::string dir = make_temp_dir(test);
  std::ofstream(dir + "/" + name) << text;
  env::ProgramInvocation invocation;
  invocation.program = program;
  invocation.arguments = {"-e", "field.e", name};
  invocation.directory = dir;
  invocation.e_file = dir + "/field.e";
  invocation.e_file_line = 1;
  return invocation;
}

inline env::Query query_at(float x, float y, float z, std::vector<float> parameters, std::uint64_t id = 0) {
  env::Query q;
  q.id = id;
  q.module.symbol = "?E";
  q.module.parameters = std::move(parameters);
  q.turtle.position = {x, y, z};
  q.turtle.position_count = 3;
  return q;
}

// Runs one pass of `field` and returns the answers.
inline std::vector<env::Answer> answer_all(env::Field& field, std::vector<env::Query>& queries, int step = 0) {
  for (std::size_t i = 0; i < queries.size(); ++i) queries[i].id = i;
  std::vector<env::Answer> answers(queries.size());
  field.answer(queries, answers, step);
  return answers;
}

// The message of the exception `action` throws, or "" if none.
template <class Action>
std::string error_of(Action&& action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}

}  // namespace sylva::test::light
