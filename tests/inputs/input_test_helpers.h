// Helpers of the input-file reader tests: test data, scratch files, and
// the message of the error a reader throws.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/vec3.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {

inline std::string input(const std::string& name) { return data_path("data/inputs/" + name); }

inline std::string write_file(const std::string& dir, const std::string& name, const std::string& content) {
  std::string path = dir + "/" + name;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The message of the ModelError `read` throws ("" if it throws none).
template <typename Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

inline void expect_vec(geometry::Vec3 actual, geometry::Vec3 expected) {
  EXPECT_FLOAT_EQ(actual.x, expected.x);
  EXPECT_FLOAT_EQ(actual.y, expected.y);
  EXPECT_FLOAT_EQ(actual.z, expected.z);
}

}  // namespace sylva::test
