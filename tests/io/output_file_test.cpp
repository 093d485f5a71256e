// Output files are written whole (temporary file + rename) — except devices
// and pipes, which a rename would replace.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "io/output_file.h"
#include "test_support.h"

namespace sylva::test {
namespace {

TEST(OutputFile, RegularFileReplacedWhole) {
  const std::string dir = make_temp_dir("output-file");
  const std::string path = dir + "/out.txt";
  io::write_output_file(path, "first\n");
  io::write_output_file(path, "second\n");
  EXPECT_EQ(read_text(path), "second\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

TEST(OutputFile, PipeIsWrittenInPlaceAndStaysAPipe) {
  const std::string dir = make_temp_dir("output-fifo");
  const std::string path = dir + "/pipe";
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  // A reader must hold the pipe open, or opening it for writing would block.
  int reader = open(path.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  io::write_output_file(path, "A(1) B\n");
  char buffer[32] = {};
  ssize_t n = read(reader, buffer, sizeof buffer - 1);
  close(reader);
  EXPECT_EQ(std::string(buffer, n > 0 ? static_cast<std::size_t>(n) : 0), "A(1) B\n");
  struct stat st;
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

}  // namespace
}  // namespace sylva::test
