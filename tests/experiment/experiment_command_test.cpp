// `sylva experiment`: the bundled example's table against separate single
// runs, the same table under MPI, errors at the plan's line before anything
// runs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "test_support.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

// The example's model and plan copied to a fresh folder (the table is
// written beside the plan).
std::string example_copy(const std::string& name) {
  const std::string dir = test::make_temp_dir(name);
  for (const char* file : {"stochastic-tree.l", "angle-sweep.toml"})
    fs::copy_file(test::example_path(std::string("experiment/") + file), dir + "/" + file);
  return dir;
}

using Row = std::map<std::string, std::string>;
std::vector<Row> read_table(const std::string& path) {
  std::istringstream in(test::read_text(path));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream h(line);
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    Row row;
    std::stringstream cells(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(cells, cell, ',') && k < header.size(); ++k) row[header[k]] = cell;
    rows.push_back(row);
  }
  return rows;
}

int count_modules(const std::string& text, const std::string& name) {
  const std::regex module("\\b" + name + "\\(");
  return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), module), std::sregex_iterator()));
}

TEST(ExperimentCommand, TheExampleSweepEqualsSeparateSingleRuns) {
  const std::string dir = example_copy("experiment-example");
  const ProcessResult result = test::run_sylva({"experiment", "angle-sweep.toml", "-j", "2"}, dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<Row> rows = read_table(dir + "/angle-sweep.csv");
  ASSERT_EQ(rows.size(), 4u * 20u * 2u);  // angles x seeds x steps
  EXPECT_TRUE(fs::file_size(dir + "/angle-width.png") > 1000);
  // Runs are numbered angle-major: run = angle index * 20 + replicate.
  std::map<std::string, std::string> apices_at_8;  // seed -> count, from the first angle
  std::map<std::string, std::string> seed_of_replicate;
  for (const Row& row : rows) {
    EXPECT_EQ(row.at("status"), "ok");
    const long run = std::stol(row.at("run"));
    // The seeds repeat across angles: replicate r has one seed.
    auto [seed, first_seen] = seed_of_replicate.emplace(row.at("replicate"), row.at("seed"));
    if (!first_seen) {
      EXPECT_EQ(seed->second, row.at("seed"));
    }
    EXPECT_EQ(std::stoi(row.at("ANGLE")), 15 + 15 * (run / 20));
    if (row.at("step") != "8") continue;
    // The draws do not depend on the angle: the same counts for each seed.
    auto [it, first] = apices_at_8.emplace(row.at("seed"), row.at("apices"));
    if (!first) {
      EXPECT_EQ(it->second, row.at("apices")) << "seed " << row.at("seed");
    }
  }
  // Seeds differ: not every replicate has the same number of apices.
  std::set<std::string> distinct;
  for (const auto& [seed, apices] : apices_at_8) distinct.insert(apices);
  EXPECT_GT(distinct.size(), 2u);
  // Three runs again, each alone through `sylva run`, counted from the string.
  for (const long run : {0L, 27L, 79L}) {
    const Row* row = nullptr;
    for (const Row& r : rows)
      if (std::stol(r.at("run")) == run && r.at("step") == "8") row = &r;
    ASSERT_NE(row, nullptr);
    const ProcessResult single = test::run_sylva({"run", "stochastic-tree.l", "--seed", row->at("seed"), "-D",
                                                  "ANGLE=" + row->at("ANGLE"), "--steps", "8", "--string", "-"}, dir);
    ASSERT_EQ(single.exit_code, 0) << single.err;
    EXPECT_EQ(std::to_string(count_modules(single.out, "A")), row->at("apices")) << "run " << run;
    EXPECT_EQ(std::to_string(count_modules(single.out, "I")), row->at("internodes")) << "run " << run;
  }
}

// A smaller plan over the example's model, for the runs below.
std::string small_plan(const std::string& dir, const std::string& extra = "") {
  std::ofstream(dir + "/small.toml") << "model = \"stochastic-tree.l\"\nreplicates = 3\nsteps = [3, 6]\n"
                                        "[parameters]\nANGLE = [20, 40]\n[measures]\napices = \"count(A)\"\n"
                                        "width = \"width\"\n" << extra;
  return dir + "/small.toml";
}

TEST(ExperimentCommand, ResultsDoNotDependOnTheNumberOfProcesses) {
  const std::string dir = example_copy("experiment-processes");
  small_plan(dir);
  ASSERT_EQ(test::run_sylva({"experiment", "small.toml", "-j", "1"}, dir).exit_code, 0);
  const std::string one = test::read_text(dir + "/small.csv");
  ASSERT_EQ(test::run_sylva({"experiment", "small.toml", "-j", "3"}, dir).exit_code, 0);
  EXPECT_EQ(test::read_text(dir + "/small.csv"), one);
}

TEST(ExperimentCommand, UnderMpiTheTableIsTheOneOfASingleMachine) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  const std::string dir = example_copy("experiment-mpi");
  small_plan(dir);
  ASSERT_EQ(test::run_sylva({"experiment", "small.toml"}, dir).exit_code, 0);
  const std::string local = test::read_text(dir + "/small.csv");
  fs::remove(dir + "/small.csv");
  const std::string command = "cd " + dir + " && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                              "SYLVA_CACHE_DIR=" SYLVA_TEST_CACHE_DIR " mpirun --oversubscribe -n 3 " SYLVA_BINARY
                              " experiment small.toml > mpi.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << test::read_text(dir + "/mpi.log");
  EXPECT_EQ(test::read_text(dir + "/small.csv"), local);
}

// The table's record names the plan and the model by their SHA-256 (as
// sha256sum computes them); saved outputs carry their run's record, and
// `sylva run --reproduce` runs one again alone.
TEST(ExperimentCommand, TheTableAndSavedOutputsRecordWhatMadeThem) {
  const std::string dir = example_copy("experiment-provenance");
  small_plan(dir, "[save]\nruns = [4]\nformats = [\"str\", \"png\"]\n");
  const ProcessResult r = test::run_sylva({"experiment", "small.toml"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string record = test::read_text(dir + "/small.csv.provenance.json");
  auto sha256sum = [&](const std::string& file) {
    const ProcessResult sum = run_process({"sha256sum", dir + "/" + file});
    return sum.out.substr(0, 64);
  };
  EXPECT_NE(record.find(sha256sum("stochastic-tree.l")), std::string::npos) << record;
  EXPECT_NE(record.find(sha256sum("small.toml")), std::string::npos) << record;
  // Run 4: ANGLE=40, replicate 1, saved at steps 3 and 6.
  const std::string seed = read_table(dir + "/small.csv").at(8).at("seed");  // run 4's first row
  for (const char* file : {"runs/run-0004/step-0003.str", "runs/run-0004/step-0006.str", "runs/run-0004/step-0006.png"})
    EXPECT_TRUE(fs::exists(dir + "/" + file)) << file;
  const ProcessResult single = test::run_sylva({"run", "stochastic-tree.l", "--seed", seed, "-D", "ANGLE=40", "--steps", "6",
                                                "--string", "-"}, dir);
  EXPECT_EQ(test::read_text(dir + "/runs/run-0004/step-0006.str"), single.out);
  const ProcessResult again = test::run_sylva({"run", "--reproduce", "runs/run-0004/step-0006.png"}, dir);
  EXPECT_EQ(again.exit_code, 0) << again.out << again.err;
}

TEST(ExperimentCommand, PlanErrorsStopBeforeAnythingRuns) {
  const std::string dir = example_copy("experiment-errors");
  std::ofstream(dir + "/bad-parameter.toml") << "model = \"stochastic-tree.l\"\n[parameters]\nANGEL = [1, 2]\n"
                                                "[measures]\nn = \"count(A)\"\n";
  ProcessResult r = test::run_sylva({"experiment", "bad-parameter.toml"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad-parameter.toml:3:9: error: the model stochastic-tree.l never uses 'ANGEL'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/bad-parameter.csv"));

  std::ofstream(dir + "/bad-module.toml") << "model = \"stochastic-tree.l\"\n[measures]\nleaves = \"count(L)\"\n";
  r = test::run_sylva({"experiment", "bad-module.toml"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad-module.toml:3:17: error: the model has no module 'L'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/bad-module.csv"));

  std::ofstream(dir + "/empty-range.toml") << "model = \"stochastic-tree.l\"\n[parameters]\n"
                                              "ANGLE = { from = 10, to = 0, step = 5 }\n[measures]\nn = \"count(A)\"\n";
  r = test::run_sylva({"experiment", "empty-range.toml"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("empty-range.toml:3:9: error: the range of 'ANGLE' has no values"), std::string::npos) << r.err;
}

TEST(ExperimentCommand, AFailingRunSaysWhyAndTheOthersGoOn) {
  const std::string dir = example_copy("experiment-failing");
  // ANGLE = oops does not compile: every run of that point fails at the build, before anything runs.
  std::ofstream(dir + "/broken.toml") << "model = \"stochastic-tree.l\"\n[parameters]\nBRANCHING = [0.5, \"oops\"]\n"
                                         "[measures]\nn = \"count(A)\"\n";
  ProcessResult r = test::run_sylva({"experiment", "broken.toml"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("does not build with -D BRANCHING=oops"), std::string::npos) << r.err;
  // A run that ends early (a step past the model's Stop) gets a row saying so.
  std::ofstream(dir + "/model-stops.l") << "#include <lpfgall.h>\nmodule A();\nderivation length: 5;\naxiom: A;\n"
                                           "A() : { if (StepNo() == 2) Stop(); produce A A; }\n";
  std::ofstream(dir + "/stops.toml") << "model = \"model-stops.l\"\nsteps = [1, 4]\n[measures]\nn = \"count(A)\"\n";
  r = test::run_sylva({"experiment", "stops.toml"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<Row> rows = read_table(dir + "/stops.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("n"), "2");
  EXPECT_EQ(rows[0].at("status"), "ok");
  EXPECT_EQ(rows[1].at("n"), "NA");
  EXPECT_EQ(rows[1].at("status"), "ended");

  // A model that aborts for some seeds: those runs' rows say why, the others are measured.
  std::ofstream(dir + "/model-aborts.l") << "#include <lpfgall.h>\n#include <cstdlib>\nmodule A();\n"
                                            "derivation length: 2;\naxiom: A;\n"
                                            "A() : { if (ran(1) < 0.2) abort(); produce A A; }\n";
  std::ofstream(dir + "/aborts.toml") << "model = \"model-aborts.l\"\nreplicates = 12\n[measures]\nn = \"count(A)\"\n";
  r = test::run_sylva({"experiment", "aborts.toml"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("failed (their rows say why)"), std::string::npos) << r.err;
  int failed = 0, measured = 0;
  for (const Row& row : read_table(dir + "/aborts.csv")) {
    if (row.at("status") == "error") {
      ++failed;
      EXPECT_FALSE(row.at("error").empty());
      EXPECT_EQ(row.at("n"), "NA");
    } else {
      ++measured;
      EXPECT_EQ(row.at("n"), "4");
    }
  }
  EXPECT_EQ(failed + measured, 12);
  EXPECT_GT(failed, 0);   // 12 seeds, each aborting with probability 1 - 0.8^3 = 0.49
  EXPECT_GT(measured, 0) << "no seed of 12 survived (P = 0.49^12)";
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// A continuous model measured at times: the logistic curve's closed form.
TEST(ExperimentCommand, ContinuousModelsAreMeasuredAtTimes) {
  const std::string dir = test::make_temp_dir("experiment-continuous");
  std::ofstream(dir + "/logistic.l") << "#include <lpfgall.h>\n#ifndef RATE\n#define RATE 1.0\n#endif\n"
                                        "module A(double);\naxiom: A(0.05);\nderivatives:\n"
                                        "A(x) : { d(x) = LogisticRate(x, RATE, 1.0); }\n";
  std::ofstream(dir + "/plan.toml") << "model = \"logistic.l\"\ntimes = [1.0, 2.5, 4.0]\n[parameters]\nRATE = [0.8, 1.2]\n"
                                       "[measures]\nx = \"sum(A, 1)\"\nn = \"count(A)\"\n";
  const ProcessResult r = test::run_sylva({"experiment", "plan.toml"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<Row> rows = read_table(dir + "/plan.csv");
  ASSERT_EQ(rows.size(), 6u);
  for (const Row& row : rows) {
    const double rate = std::stod(row.at("RATE")), t = std::stod(row.at("time"));
    const double expected = 1.0 / (1.0 + (1.0 / 0.05 - 1.0) * std::exp(-rate * t));
    EXPECT_NEAR(std::stod(row.at("x")), expected, 1e-5) << "RATE " << rate << " t " << t;
    EXPECT_EQ(row.at("n"), "1");
  }
}

}  // namespace
}  // namespace sylva
