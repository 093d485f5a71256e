// Output files are written whole (temporary file + rename) — except devices
// and pipes, which a rename would replace. A file replaced keeps its
// permissions; a symbolic link is written through; standard output is checked.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdio_ext.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>

#include "io/output_file.h"
#include "support/diagnostic.h"
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

mode_t permissions(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(stat(path.c_str(), &st), 0) << path;
  return st.st_mode & 07777;
}

std::size_t entries(const std::string& dir) {
  return static_cast<std::size_t>(
      std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
}

TEST(OutputFile, AReplacedFileKeepsItsPermissions) {
  const std::string dir = make_temp_dir("output-permissions");
  const std::string path = dir + "/out.txt";
  io::write_output_file(path, "first\n");
  const mode_t umask_now = umask(0);
  umask(umask_now);
  EXPECT_EQ(permissions(path), 0666 & ~umask_now);  // a new file: the umask's
  ASSERT_EQ(chmod(path.c_str(), 0600), 0);
  io::write_output_file(path, "second\n");
  EXPECT_EQ(permissions(path), 0600u);
  ASSERT_EQ(chmod(path.c_str(), 0664), 0);  // more than the umask lets through
  io::write_output_file(path, "third\n");
  EXPECT_EQ(permissions(path), 0664u);
  EXPECT_EQ(read_text(path), "third\n");
}

TEST(OutputFile, ASymbolicLinkIsWrittenThrough) {
  namespace fs = std::filesystem;
  const std::string dir = make_temp_dir("output-symlink");
  fs::create_directory(dir + "/real");
  io::write_output_file(dir + "/real/out.txt", "old\n");
  ASSERT_EQ(chmod((dir + "/real/out.txt").c_str(), 0600), 0);
  fs::create_symlink("real/out.txt", dir + "/link.txt");     // relative to the link's folder
  fs::create_symlink(dir + "/link.txt", dir + "/link2.txt");  // a chain, absolute
  io::write_output_file(dir + "/link2.txt", "new\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/link.txt")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/link2.txt")));
  EXPECT_EQ(read_text(dir + "/real/out.txt"), "new\n");
  EXPECT_EQ(permissions(dir + "/real/out.txt"), 0600u);
  EXPECT_EQ(entries(dir), 3u);  // no temporary file left in either folder
  EXPECT_EQ(entries(dir + "/real"), 1u);
  // A link to nothing yet: its target is made.
  fs::create_symlink("real/made.txt", dir + "/dangling.txt");
  io::write_output_file(dir + "/dangling.txt", "made\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/dangling.txt")));
  EXPECT_EQ(read_text(dir + "/real/made.txt"), "made\n");
}

TEST(OutputFile, ALinkToADeviceWritesTheDevice) {
  namespace fs = std::filesystem;
  const std::string dir = make_temp_dir("output-device-link");
  fs::create_symlink("/dev/null", dir + "/null");
  io::write_output_file(dir + "/null", "nothing\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/null")));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(OutputFile, ALinkOfAnotherUsersIsNotFollowed) {
  namespace fs = std::filesystem;
  const std::string dir = make_temp_dir("output-foreign-link");
  fs::create_symlink("mine.txt", dir + "/planted.txt");
  const uid_t other = geteuid() == 65534 ? 65533 : 65534;
  if (lchown((dir + "/planted.txt").c_str(), other, static_cast<gid_t>(-1)) != 0)
    GTEST_SKIP() << "only root can give a link to another user";
  EXPECT_THROW(io::write_output_file(dir + "/planted.txt", "x"), ModelError);
  EXPECT_FALSE(fs::exists(dir + "/mine.txt"));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(OutputFile, ALoopOfLinksIsAnError) {
  namespace fs = std::filesystem;
  const std::string dir = make_temp_dir("output-symlink-loop");
  fs::create_symlink("b", dir + "/a");
  fs::create_symlink("a", dir + "/b");
  try {
    io::write_output_file(dir + "/a", "x");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("Too many levels of symbolic links"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/a")));
  EXPECT_EQ(entries(dir), 2u);
}

TEST(OutputFile, AFailedWriteToStandardOutputIsAnError) {
  // Standard output is a pipe whose reader has gone; SIGPIPE is ignored, as
  // some parents leave it, so the write fails with EPIPE.
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  int pipe_ends[2];
  ASSERT_EQ(pipe(pipe_ends), 0);
  close(pipe_ends[0]);
  dup2(pipe_ends[1], STDOUT_FILENO);
  close(pipe_ends[1]);
  void (*previous)(int) = std::signal(SIGPIPE, SIG_IGN);
  std::string error;
  try {
    io::write_output_file("-", "A(1)\n");
  } catch (const ModelError& e) {
    error = e.what();
  }
  std::signal(SIGPIPE, previous);
  __fpurge(stdout);  // what could not be written is not written later
  dup2(saved, STDOUT_FILENO);
  close(saved);
  std::clearerr(stdout);
  EXPECT_EQ(error, "sylva: error: cannot write to standard output: Broken pipe");
}

}  // namespace
}  // namespace sylva::test
