// `sylva run --reproduce FILE` (docs/provenance.md): a fresh output is
// reproduced; an edited model, an altered record and a file without one are
// reported as such, with their exit statuses (1, 1, 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "api/provenance.h"
#include "test_support.h"

namespace sylva::test {
namespace {

namespace fs = std::filesystem;

std::string show(const ProcessResult& r) {
  return "exit status " + std::to_string(r.exit_code) + "\n--- stdout ---\n" + r.out + "\n--- stderr ---\n" + r.err;
}

// A stochastic model: its string depends on the seed and on START (a -D).
constexpr const char* kModel =
    "#include <lpfgall.h>\n"
    "#ifndef START\n#define START 2\n#endif\n"
    "derivation length: 4;\n"
    "module A(float);\n"
    "Axiom: A(START);\n"
    "A(x) : { produce F(1) A(x + ran(1)); }\n";

std::string folder_with_model(const std::string& name) {
  const std::string dir = make_temp_dir("reproduce-" + name);
  std::ofstream(dir + "/model.l") << kModel;
  std::ofstream(dir + "/model.v") << "line style: pixel\n";
  return dir;
}

TEST(Reproduce, AFreshOutputIsReproduced) {
  const std::string dir = folder_with_model("fresh");
  ProcessResult r = run_sylva({"run", "model.l", "model.v", "-DSTART=5", "--seed", "17", "-o", "out.obj", "-o", "out.svg",
                               "--string", "out.str"},
                              dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  const std::optional<RunRecord> record = read_run_record(dir + "/out.obj");
  ASSERT_TRUE(record.has_value());
  EXPECT_EQ(record->defines, std::vector<std::string>{"START=5"});
  EXPECT_EQ(record->seed, 17);
  EXPECT_EQ(record->step, 4);
  EXPECT_EQ(record->string_sha256, sha256_hex(read_text(dir + "/out.str")));
  ASSERT_EQ(record->inputs.size(), 1u);
  EXPECT_EQ(fs::path(record->inputs[0].path).filename(), "model.v");

  for (const char* file : {"out.obj", "out.svg", "out.str", "out.str.provenance.json"}) {
    r = run_sylva({"run", "--reproduce", file}, dir);
    EXPECT_EQ(r.exit_code, 0) << file << ": " << show(r);
    EXPECT_EQ(r.out, std::string("reproduced: ") + file + " (string sha256 " + record->string_sha256 + ")\n");
  }
  // From another folder: the record names the files by absolute path.
  r = run_sylva({"run", "--reproduce", dir + "/out.obj"}, make_temp_dir("reproduce-elsewhere"));
  EXPECT_EQ(r.exit_code, 0) << show(r);
}

TEST(Reproduce, AnEditedModelIsNamed) {
  const std::string dir = folder_with_model("edited");
  ProcessResult r = run_sylva({"run", "model.l", "-o", "out.ply"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  std::ofstream(dir + "/model.l", std::ios::app) << "// an edit\n";
  r = run_sylva({"run", "--reproduce", "out.ply"}, dir);
  EXPECT_EQ(r.exit_code, 1) << show(r);
  EXPECT_NE(r.err.find(fs::path(dir + "/model.l").lexically_normal().string() + ": the model has changed"),
            std::string::npos)
      << show(r);
  EXPECT_TRUE(r.out.empty()) << show(r);
  // An edited input file likewise.
  r = run_sylva({"run", "model.l", "model.v", "-o", "out2.obj"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  std::ofstream(dir + "/model.v", std::ios::app) << "contour sides: 8\n";
  r = run_sylva({"run", "--reproduce", "out2.obj"}, dir);
  EXPECT_EQ(r.exit_code, 1) << show(r);
  EXPECT_NE(r.err.find("model.v: the input file has changed"), std::string::npos) << show(r);
}

TEST(Reproduce, AnAlteredStringHashFails) {
  const std::string dir = folder_with_model("altered");
  ProcessResult r = run_sylva({"run", "model.l", "--seed", "3", "--string", "out.str"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  nlohmann::json record = nlohmann::json::parse(read_text(dir + "/out.str.provenance.json"));
  record["string_sha256"] = sha256_hex("something else");
  std::ofstream(dir + "/altered.provenance.json") << record.dump(2);
  r = run_sylva({"run", "--reproduce", "altered.provenance.json"}, dir);
  EXPECT_EQ(r.exit_code, 1) << show(r);
  EXPECT_NE(r.err.find("not reproduced"), std::string::npos) << show(r);
  EXPECT_NE(r.err.find(sha256_hex("something else")), std::string::npos) << show(r);
  // The seed matters: another seed is another string.
  record = nlohmann::json::parse(read_text(dir + "/out.str.provenance.json"));
  record["seed"] = 4;
  std::ofstream(dir + "/reseeded.provenance.json") << record.dump(2);
  r = run_sylva({"run", "--reproduce", "reseeded.provenance.json"}, dir);
  EXPECT_EQ(r.exit_code, 1) << show(r);
}

TEST(Reproduce, AFileWithoutARecordIsAnError) {
  const std::string dir = folder_with_model("none");
  std::ofstream(dir + "/plain.obj") << "v 0 0 0\n";
  ProcessResult r = run_sylva({"run", "--reproduce", "plain.obj"}, dir);
  EXPECT_EQ(r.exit_code, 2) << show(r);
  EXPECT_NE(r.err.find("plain.obj: no provenance record"), std::string::npos) << show(r);
  r = run_sylva({"run", "--reproduce", "missing.png"}, dir);
  EXPECT_EQ(r.exit_code, 1) << show(r);
  EXPECT_NE(r.err.find("missing.png"), std::string::npos) << show(r);
}

}  // namespace
}  // namespace sylva::test
