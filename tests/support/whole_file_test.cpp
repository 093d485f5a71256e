// Files read and written whole.
#include "support/whole_file.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

namespace sylva {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("sylva_whole_file_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(WholeFile, ReadsEveryByte) {
  fs::path dir = fresh_folder("read");
  const std::string bytes("line one\nline\0two\r\n", 19);
  std::ofstream(dir / "f", std::ios::binary) << bytes;
  WholeFile file = read_whole_file((dir / "f").string());
  ASSERT_TRUE(file);
  EXPECT_EQ(file.bytes, bytes);
  std::ofstream(dir / "empty", std::ios::binary);
  WholeFile empty = read_whole_file((dir / "empty").string());
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty.bytes, "");
  fs::remove_all(dir);
}

TEST(WholeFile, FailuresSaySo) {
  fs::path dir = fresh_folder("failures");
  EXPECT_EQ(read_whole_file((dir / "missing").string()).failure, WholeFile::Failure::CannotOpen);
  EXPECT_EQ(read_whole_file(dir.string()).failure, WholeFile::Failure::IsFolder);
  EXPECT_FALSE(read_whole_file(dir.string()));
  fs::remove_all(dir);
}

TEST(WholeFile, WritesAtomicallyOverTheOldContent) {
  fs::path dir = fresh_folder("write");
  const std::string path = (dir / "out.txt").string();
  ASSERT_EQ(write_file_atomically(path, "first"), 0);
  ASSERT_EQ(write_file_atomically(path, "second"), 0);
  EXPECT_EQ(read_whole_file(path).bytes, "second");
  // Only the file itself is left: the temporary file was renamed.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(WholeFile, AFailedWriteLeavesNothing) {
  fs::path dir = fresh_folder("failed_write");
  EXPECT_EQ(write_file_atomically((dir / "no_such_folder" / "out.txt").string(), "x"), ENOENT);
  // Renaming over a folder fails; the folder stays and no temporary is left.
  fs::create_directory(dir / "taken");
  EXPECT_NE(write_file_atomically((dir / "taken").string(), "x"), 0);
  EXPECT_TRUE(fs::is_directory(dir / "taken"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
