// A model in the studio, run by the real worker program: steps, errors
// placed in the source, crashes survived, parameters applied to copies.
#include "studio/model_session.h"

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::studio {
namespace {

using nlohmann::json;

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Each step adds BRANCHES modules B and one F: after n steps the string
// holds 1 + n * (1 + BRANCHES) modules. At step CRASH_AT the production
// writes through a null pointer.
const char* kModel = R"(#include <lpfgall.h>
#define BRANCHES 2
#define CRASH_AT 99
derivation length: 4;
module A(int);
module B;
Axiom: A(0);
production:
A(n) : {
  if (n + 1 == CRASH_AT) { volatile int* p = nullptr; *p = 1; }
  nproduce F(1);
  for (int i = 0; i < BRANCHES; ++i) nproduce B;
  produce A(n + 1);
}
)";

SessionOptions options_for(const std::string& model) {
  SessionOptions o;
  o.model = model;
  o.cache_dir = SYLVA_TEST_CACHE_DIR;
  o.worker_command = {SYLVA_BINARY, "studio-worker"};
  o.time_limit_seconds = 60;
  return o;
}

TEST(ModelSession, StepsRunAndRewinds) {
  const std::string dir = test::make_temp_dir("session-steps");
  write(dir + "/plant.l", kModel);
  ModelSession session(options_for(dir + "/plant.l"));
  session.reload();
  json state = session.state_json();
  ASSERT_TRUE(state["error"].is_null()) << state["error"].dump();
  EXPECT_EQ(state["step"], 0);
  EXPECT_EQ(state["modules"], 1);
  EXPECT_EQ(state["derivation_length"], 4);
  const std::uint64_t first_scene = session.scene().second;

  session.step(1);
  state = session.state_json();
  EXPECT_EQ(state["step"], 1);
  EXPECT_EQ(state["modules"], 1 + 3);
  EXPECT_GT(session.scene().second, first_scene);
  // The string is F(1) B B A(1); without interpretation rules the picture's
  // numbering is the string's.
  const WorkerMessage module = session.ask({{"op", "module"}, {"view", 0}, {"index", 3}});
  EXPECT_EQ(module.json["text"], "A(1)");
  EXPECT_EQ(module.json["parameters"], json::array({"1"}));
  EXPECT_EQ(module.json["string_index"], 3);
  EXPECT_EQ(module.json["step"], 1);  // A(1) was made by the first step
  const WorkerMessage counts = session.ask({{"op", "counts"}});
  EXPECT_EQ(counts.json["counts"][0], json({{"name", "B"}, {"count", 2}}));
  const WorkerMessage found = session.ask({{"op", "string"}, {"offset", 0}, {"limit", 2}, {"search", "B"}});
  EXPECT_EQ(found.json["items"].size(), 2u);
  EXPECT_EQ(found.json["matches"], json::array({1, 2}));
  // An export is written in a private folder of its own, removed once read.
  const WorkerMessage exported = session.ask({{"op", "export"}, {"format", "ply"}, {"view", 0}});
  EXPECT_EQ(exported.payload.substr(0, 3), "ply");

  session.run_to(-1);
  state = session.state_json();
  EXPECT_EQ(state["step"], 4);
  EXPECT_EQ(state["modules"], 1 + 4 * 3);
  EXPECT_TRUE(state["finished"]);
  session.step(1);  // nothing past the derivation length
  EXPECT_EQ(session.state_json()["step"], 4);

  session.rewind();
  EXPECT_EQ(session.state_json()["step"], 0);
  // A picture is binary glTF.
  EXPECT_EQ(session.scene().first->glb.substr(0, 4), "glTF");
  EXPECT_EQ(session.scene().first->instances, "");  // a small scene stays whole
}

TEST(ModelSession, ATranslationErrorIsPlacedInTheSourceAndThePictureStays) {
  const std::string dir = test::make_temp_dir("session-error");
  write(dir + "/plant.l", kModel);
  ModelSession session(options_for(dir + "/plant.l"));
  session.reload();
  const std::uint64_t good = session.scene().second;
  std::string broken = kModel;
  broken.replace(broken.find("nproduce F(1);"), 14, "nproduce F;   ");
  write(dir + "/plant.l", broken);
  session.reload();
  const json error = session.state_json()["error"];
  ASSERT_FALSE(error.is_null());
  EXPECT_EQ(error["file"], "plant.l");
  EXPECT_EQ(error["line"], 11);
  EXPECT_EQ(error["source_line"], "  nproduce F;   ");
  EXPECT_EQ(session.scene().second, good);
  ASSERT_TRUE(session.scene().first);
}

TEST(ModelSession, ACrashIsReportedAndTheNextSaveRecovers) {
  const std::string dir = test::make_temp_dir("session-crash");
  std::string crashing = kModel;
  crashing.replace(crashing.find("CRASH_AT 99"), 11, "CRASH_AT 2 ");
  write(dir + "/plant.l", crashing);
  ModelSession session(options_for(dir + "/plant.l"));
  session.reload();
  session.step(1);
  session.step(1);
  json state = session.state_json();
  ASSERT_FALSE(state["error"].is_null());
  EXPECT_EQ(state["error"]["kind"], "crash");
  EXPECT_EQ(state["error"]["step"], 2);
  // The worker's own report: where in the model, and the step.
  const std::string message = state["error"]["message"];
  EXPECT_NE(message.find("plant.l:9: error: model crashed in production (SIGSEGV, null pointer) (step 2)"),
            std::string::npos)
      << message;
  EXPECT_EQ(state["step"], 1);  // the last good state stays on show

  write(dir + "/plant.l", kModel);
  session.reload();
  state = session.state_json();
  EXPECT_TRUE(state["error"].is_null()) << state["error"].dump();
  EXPECT_EQ(state["step"], 1);  // derived back to the last good step
  session.step(2);
  EXPECT_EQ(session.state_json()["step"], 3);
}

TEST(ModelSession, AParameterChangesTheRunNotTheFile) {
  const std::string dir = test::make_temp_dir("session-param");
  write(dir + "/plant.l", kModel);
  ModelSession session(options_for(dir + "/plant.l"));
  session.reload();
  session.run_to(2);
  json state = session.state_json();
  ASSERT_EQ(state["params"][0]["define"], "BRANCHES");
  session.set_parameter("p0", 5);
  state = session.state_json();
  EXPECT_TRUE(state["error"].is_null()) << state["error"].dump();
  EXPECT_EQ(state["step"], 2);                 // derived back to where it was
  EXPECT_EQ(state["modules"], 1 + 2 * 6);      // with five branches a step
  EXPECT_TRUE(state["params_modified"]);
  EXPECT_EQ(test::read_text(dir + "/plant.l"), kModel);

  session.save_parameters();
  std::string saved = kModel;
  saved.replace(saved.find("BRANCHES 2"), 10, "BRANCHES 5");
  EXPECT_EQ(test::read_text(dir + "/plant.l"), saved);
  EXPECT_FALSE(session.state_json()["params_modified"]);
}

TEST(ModelSession, ThePageLooksAtThePictureCpfgFramesOffTheLineOfSight) {
  // cpfg looks from the viewpoint at the view reference point (the origin)
  // and centres the plant's box in the window: a line from y = 0 to y = 10 is
  // in the middle, so the page's camera looks at y = 5.
  const std::string dir = test::make_temp_dir("session-cpfg-view");
  write(dir + "/plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: F(10)\nendlsystem\n");
  write(dir + "/plant.v", "viewpoint: 0,0,300\nview reference point: 0,0,0\nprojection: parallel\n");
  SessionOptions options = options_for(dir + "/plant.l");
  options.inputs = {io::InputFile(dir + "/plant.v")};
  ModelSession session(options);
  session.reload();
  const json view = session.state_json()["view"];
  ASSERT_TRUE(view.is_object()) << session.state_json()["error"].dump();
  EXPECT_NEAR(view["target"][1].get<double>(), 5, 1e-3);
  EXPECT_NEAR(view["eye"][1].get<double>(), 5, 1e-3);
  EXPECT_NEAR(view["target"][0].get<double>(), 0, 1e-3);
}

TEST(ModelSession, AWatcherReloadsOnlyWhatChangedSinceTheLastOpen) {
  const std::string dir = test::make_temp_dir("session-watch");
  write(dir + "/plant.l", kModel);
  ModelSession session(options_for(dir + "/plant.l"));
  session.reload();
  const std::uint64_t opened = session.scene().second;
  session.reload_if_changed();  // nothing changed: no new picture
  EXPECT_EQ(session.scene().second, opened);
  std::string edited = kModel;
  edited.replace(edited.find("BRANCHES 2"), 10, "BRANCHES 3");
  write(dir + "/plant.l", edited);
  session.reload_if_changed();
  EXPECT_GT(session.scene().second, opened);
  EXPECT_EQ(session.state_json()["params"][0]["value"], 3);
}

}  // namespace
}  // namespace sylva::studio
