#include "test_support.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "api/simulation.h"
#include "io/string_text.h"

namespace sylva::test {
namespace fs = std::filesystem;

std::string data_path(const std::string& relative) { return std::string(SYLVA_TEST_DATA_DIR) + "/" + relative; }
std::string example_path(const std::string& relative) { return std::string(SYLVA_EXAMPLES_DIR) + "/" + relative; }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string derive_string(const std::string& model, int steps) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(model, options);
  simulation.run(steps);
  std::string text = io::format_string(simulation.string(), simulation.types());
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

ProcessResult run_sylva(const std::vector<std::string>& args, const std::string& working_dir) {
  std::vector<std::string> argv = {"/usr/bin/env", "-C", working_dir,
                                   std::string("SYLVA_CACHE_DIR=") + SYLVA_TEST_CACHE_DIR, SYLVA_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_process(argv);
}

std::vector<fs::path> model_folders(const std::string& dir) {
  std::vector<fs::path> folders;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_directory() && fs::exists(entry.path() / "lsystem.l")) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  return folders;
}

namespace {

// The folders made for this test program, removed when it exits so that runs
// leave nothing behind in the temporary directory.
struct TempDirs {
  std::vector<fs::path> made;
  ~TempDirs() {
    std::error_code ignored;
    for (const fs::path& dir : made) fs::remove_all(dir, ignored);
  }
};

TempDirs& temp_dirs() {
  static TempDirs dirs;
  return dirs;
}

}  // namespace

std::string make_temp_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("sylva-test-" + name + "-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  temp_dirs().made.push_back(dir);
  return dir.string();
}

std::string write_temp_file(const std::string& folder, const std::string& file_name, const std::string& text) {
  const std::string path = make_temp_dir(folder) + "/" + file_name;
  std::ofstream(path) << text;
  return path;
}

bool kernel_populates_pages() {
#ifdef MADV_POPULATE_WRITE
  const std::size_t page = 4096;
  void* probe = mmap(nullptr, page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (probe == MAP_FAILED) return false;
  const bool populated = madvise(probe, page, MADV_POPULATE_WRITE) == 0;
  munmap(probe, page);
  return populated;
#else
  return false;
#endif
}

}  // namespace sylva::test
