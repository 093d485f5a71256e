// Parallel derivation gives the serial string: every model of examples/ and
// of the golden sets derived on one thread and on four, the string cut into
// chunks of a few modules so that even these small strings are split (across
// predecessors of several modules, cuts and branches), compared byte for
// byte; and the keyed random mode gives one string at any thread count.
#include <gtest/gtest.h>
#include <linux/perf_event.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "io/string_text.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

// Steps enough to grow each string well past a few chunks, few enough to
// keep the models whose strings grow fast quick.
constexpr int kMaxSteps = 12;

struct Derived {
  std::string string;  // the final string, or the error that ended the run
  std::string explanation;
};

Derived derive(const std::string& model, int threads, bool keyed = false, int steps = -1) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.threads = threads;
  options.keyed_random = keyed;
  options.parallel_chunk_bytes = 48;
  Derived run;
  try {
    Simulation simulation(model, options, [](const std::string&) {});
    run.explanation = simulation.parallel_explanation();
    if (steps < 0) steps = std::min(simulation.derivation_length(), kMaxSteps);
    simulation.run(steps);
    run.string = io::format_string(simulation.string(), simulation.types());
  } catch (const std::exception& e) {
    run.string = std::string("error: ") + e.what();
  }
  return run;
}

std::vector<std::string> all_models() {
  std::vector<std::string> models;
  for (const auto& entry : fs::directory_iterator(example_path("")))
    if (entry.is_directory())
      for (const auto& file : fs::directory_iterator(entry.path()))
        if (file.path().extension() == ".l") models.push_back(file.path().string());
  for (const char* set : {"golden", "golden-cpfg"})
    for (const fs::path& folder : model_folders(data_path(set))) models.push_back((folder / "lsystem.l").string());
  std::sort(models.begin(), models.end());
  return models;
}

class EveryModel : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryModel, GivesTheSerialStringOnFourThreads) {
  const Derived one = derive(GetParam(), 1), four = derive(GetParam(), 4);
  EXPECT_EQ(one.string, four.string);
}

INSTANTIATE_TEST_SUITE_P(ParallelDerivation, EveryModel, ::testing::ValuesIn(all_models()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = fs::path(info.param).parent_path().filename().string() + "_" +
                                              fs::path(info.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name + "_" + std::to_string(info.index);
                         });

// Not a vacuous comparison: the models above that run in parallel.
TEST(ParallelDerivation, ManyModelsRunInParallel) {
  int parallel = 0;
  for (const char* name : {"koch/koch.l", "branching/branching.l", "context-developmental/context-developmental.l",
                           "decomposition/decomposition.l", "snowflake/snowflake.l"})
    if (derive(example_path(name), 4, false, 0).explanation.find("productions: parallel") != std::string::npos)
      ++parallel;
  EXPECT_GE(parallel, 3);
}

TEST(ParallelDerivation, ExplainsWhichRuleKeepsARunSerial) {
  const std::string model = write_temp_file("parallel-explain", "counter.l",
                                            "#include <lpfgall.h>\n"
                                            "int count = 0;\n"
                                            "derivation length: 3;\n"
                                            "module A;\n"
                                            "axiom: A;\n"
                                            "A :\n"
                                            "{\n"
                                            "  count = count + 1;\n"
                                            "  produce A A;\n"
                                            "}\n");
  const Derived run = derive(model, 4);
  EXPECT_NE(run.explanation.find("productions: serial: "), std::string::npos) << run.explanation;
  EXPECT_NE(run.explanation.find("counter.l:6: production assigns `count`"), std::string::npos) << run.explanation;
  EXPECT_EQ(run.string, "A A A A A A A A\n");
  EXPECT_EQ(derive(example_path("koch/koch.l"), 4).explanation.rfind("productions: parallel on 4 threads", 0), 0u);
}

// Page faults taken by this process's threads from now on, as the kernel's
// page-fault event counts them: each write that traps on a page not yet in,
// and not the pages faulted in a stretch at once.
class PageFaultCounter {
 public:
  PageFaultCounter() {
    perf_event_attr attr{};
    attr.size = sizeof attr;
    attr.type = PERF_TYPE_SOFTWARE;
    attr.config = PERF_COUNT_SW_PAGE_FAULTS;
    for (const auto& task : fs::directory_iterator("/proc/self/task")) {
      const long fd = syscall(SYS_perf_event_open, &attr, std::stoi(task.path().filename().string()), -1, -1, 0);
      if (fd >= 0) fds_.push_back(static_cast<int>(fd));
    }
  }
  ~PageFaultCounter() {
    for (int fd : fds_) close(fd);
  }
  bool counting() const { return !fds_.empty(); }
  std::uint64_t faults() const {
    std::uint64_t sum = 0;
    for (int fd : fds_) {
      std::uint64_t n = 0;
      if (read(fd, &n, sizeof n) == sizeof n) sum += n;
    }
    return sum;
  }

 private:
  std::vector<int> fds_;
};

// A parallel pass over a 3 MB string: its pages come in a stretch at a
// time, as a serial pass's do (each part's place in the next string,
// faulted in before the part is copied there), and its parts land where a
// serial pass puts them.
TEST(ParallelDerivation, FaultsInItsPagesAStretchAtATime) {
  const std::string model = write_temp_file("parallel-pages", "koch.l",
                                            "#include <lpfgall.h>\n"
                                            "derivation length: 10;\n"
                                            "module A(float);\n"
                                            "module B(float);\n"
                                            "axiom: A(1);\n"
                                            "A(x) :\n"
                                            "  produce A(x / 3) B(60) A(x / 3) B(-120) A(x / 3) B(60) A(x / 3);\n");
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.threads = 2;
  Simulation simulation(model, options, [](const std::string&) {});
  for (int step = 1; step < 10; ++step) simulation.step();  // the helper thread is started
  const PageFaultCounter counter;
  simulation.step();  // 1 048 576 A and 1 048 575 B: 12.6 MB
  ASSERT_EQ(simulation.string().size_bytes(), (1048576u + 1048575u) * 6u);
  EXPECT_TRUE(simulation.parallel_explanation().find("productions: parallel") != std::string::npos);
  // The step writes 3080 fresh pages; copied into without being faulted in
  // first, 2881 of them fault. Not checked where the kernel faults pages in
  // one by one, or where this process may not count its faults.
  if (kernel_populates_pages() && counter.counting()) {
    EXPECT_LT(counter.faults(), 20u);
  }
  // And the parts are where a serial pass puts them.
  options.threads = 1;
  Simulation serial(model, options, [](const std::string&) {});
  serial.run(10);
  ASSERT_EQ(serial.string().size_bytes(), simulation.string().size_bytes());
  EXPECT_EQ(std::memcmp(serial.string().data(), simulation.string().data(), serial.string().size_bytes()), 0);
}

// A step that grows far more than the steps before it: the room reserved
// for the next string runs out, and the parts past it are copied in after
// the pass. The string is still the serial one.
TEST(ParallelDerivation, AStepThatOutgrowsItsRoomGivesTheSerialString) {
  std::string axiom;
  for (int k = 0; k < 200; ++k) axiom += " A(0)";
  std::string burst;
  for (int k = 0; k < 30; ++k) burst += " B";
  const std::string model = write_temp_file("parallel-burst", "burst.l",
                                            "#include <lpfgall.h>\n"
                                            "derivation length: 7;\n"
                                            "module A(int);\n"
                                            "module B;\n"
                                            "axiom:" + axiom + ";\n"
                                            "A(n) : { if (n < 5) produce A(n + 1); else produce" + burst + "; }\n");
  const Derived one = derive(model, 1), four = derive(model, 4);
  EXPECT_NE(four.explanation.find("productions: parallel"), std::string::npos) << four.explanation;
  ASSERT_EQ(std::count(one.string.begin(), one.string.end(), 'B'), 6000);
  EXPECT_EQ(one.string, four.string);
}

// The next parallel pass cuts the string where the last one noted that
// modules start, walking it only where none was noted nearby: each noted
// start must be a module's, and they must lie close enough together that
// walking is the exception.
TEST(ParallelDerivation, NotesWhereModulesStartForTheNextPass) {
  // The starts of the productions' strings, and of their decompositions.
  const std::string rules =
      "#include <lpfgall.h>\n"
      "derivation length: 12;\n"
      "module A(float);\n"
      "module B(int, float);\n"
      "module C;\n"
      "module D;\n"
      "axiom: A(1) B(2, 3) C;\n"
      "A(x) : produce A(x + 1) C B(1, x) A(x);\n"
      "B(i, x) : produce C A(x) C;\n";
  for (const std::string& model : {write_temp_file("parallel-starts", "productions.l", rules),
                                   write_temp_file("parallel-starts-decomposed", "decomposed.l",
                                                   rules + "decomposition:\nC : produce D;\n")}) {
    for (int threads : {1, 4}) {
      SCOPED_TRACE(model + " on " + std::to_string(threads) + " threads");
      SimulationOptions options;
      options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
      options.threads = threads;
      options.parallel_chunk_bytes = 400;  // starts noted at least 100 bytes apart
      Simulation simulation(model, options, [](const std::string&) {});
      // Checked after every step, before the next pass relies on them.
      for (int step = 1; step <= 12; ++step) {
        simulation.step();
        const ModuleString& string = simulation.string();
        const StringView view = string.view(simulation.types());
        std::vector<std::size_t> starts;
        for (std::size_t at = 0; at < view.end; at = view.next(at)) starts.push_back(at);
        const std::vector<std::size_t>& noted = string.known_module_starts();
        ASSERT_FALSE(noted.empty()) << "step " << step;
        std::size_t previous = 0;
        for (std::size_t start : noted) {
          ASSERT_TRUE(std::binary_search(starts.begin(), starts.end(), start))
              << start << " is not a module's start, step " << step;
          // Between two rules applied lie a few bytes of modules without
          // rules at most, and no successor is longer than 64 bytes.
          EXPECT_LT(start - previous, 100u + 64u);
          previous = start;
        }
        EXPECT_LT(string.size_bytes() - previous, 100u + 64u);
      }
      EXPECT_GT(simulation.string().size_bytes(), 8000u);  // split into many chunks
    }
  }
}

// A stochastic model: what each module becomes depends on ran().
const char* const kStochastic =
    "#include <lpfgall.h>\n"
    "derivation length: 9;\n"
    "module A(float);\n"
    "module B(float);\n"
    "axiom: A(0) B(1) A(2);\n"
    "A(x) :\n"
    "{\n"
    "  if (ran(1) < 0.5) produce A(x + ran(1)) B(x);\n"
    "  produce A(x) SB() A(ran(2)) EB();\n"
    "}\n"
    "B(x) < A(y) :\n"
    "{\n"
    "  produce A(x * y) B(ran(1));\n"
    "}\n"
    "decomposition:\n"
    "B(x) :\n"
    "{\n"
    "  if (ran(1) < 0.3) produce B(x) B(ran(1));\n"
    "  produce B(x);\n"
    "}\n";

TEST(ParallelDerivation, KeyedRandomGivesOneStringAtAnyThreadCount) {
  const std::string model = write_temp_file("parallel-keyed", "stochastic.l", kStochastic);
  const Derived one = derive(model, 1, true), two = derive(model, 2, true), four = derive(model, 4, true);
  EXPECT_EQ(four.explanation.find("serial"), std::string::npos) << four.explanation;
  EXPECT_GT(one.string.size(), 1000u);
  EXPECT_EQ(one.string, two.string);
  EXPECT_EQ(one.string, four.string);
  // lpfg's sequence keeps productions that draw serial, and its own string.
  const Derived lpfg = derive(model, 4, false);
  EXPECT_NE(lpfg.explanation.find("calls ran()"), std::string::npos) << lpfg.explanation;
  EXPECT_EQ(lpfg.string, derive(model, 1, false).string);
  EXPECT_NE(lpfg.string, one.string);
}

}  // namespace
}  // namespace sylva::test
