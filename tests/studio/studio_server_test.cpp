// What the studio's server lets through: its own names only, its token when
// it has one, and no file outside the model's folder.
#include "studio/studio_server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <fstream>
#include <thread>

#include "studio/model_session.h"
#include "test_support.h"

namespace sylva::studio {
namespace {

class StudioServerTest : public ::testing::Test {
 protected:
  void start(const std::string& token = "") {
    dir_ = test::make_temp_dir("studio-server");
    std::filesystem::create_directories(dir_ + "/model");
    std::ofstream(dir_ + "/model/plant.l") << "Axiom: F(1);\n";
    std::ofstream(dir_ + "/secret.txt") << "secret\n";
    std::filesystem::create_symlink(dir_ + "/secret.txt", dir_ + "/model/out.txt");
    SessionOptions options;
    options.model = dir_ + "/model/plant.l";
    options.worker_command = {SYLVA_BINARY, "studio-worker"};
    session_ = std::make_unique<ModelSession>(options);
    ServerOptions server_options;
    server_options.token = token;
    server_ = std::make_unique<StudioServer>(*session_, server_options);
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->serve(); });
  }
  void TearDown() override {
    if (server_) server_->stop();
    if (thread_.joinable()) thread_.join();
  }
  int status(const std::string& path, const httplib::Headers& headers = {}) {
    httplib::Client client("127.0.0.1", port_);
    const httplib::Result result = client.Get(path, headers);
    return result ? result->status : -1;
  }

  std::string dir_;
  std::unique_ptr<ModelSession> session_;
  std::unique_ptr<StudioServer> server_;
  std::thread thread_;
  int port_ = 0;
};

TEST_F(StudioServerTest, ServesThePageAndTheModelsFolder) {
  start();
  EXPECT_EQ(status("/"), 200);
  EXPECT_EQ(status("/api/state"), 200);
  EXPECT_EQ(status("/files/plant.l"), 200);
  EXPECT_EQ(status("/api/scene.glb"), 204);  // no picture before the model has run
}

TEST_F(StudioServerTest, RefusesFilesOutsideTheModelsFolder) {
  start();
  EXPECT_EQ(status("/files/../secret.txt"), 403);
  EXPECT_EQ(status("/files/%2e%2e/secret.txt"), 403);
  EXPECT_EQ(status("/files/out.txt"), 403);  // a link leading out
  EXPECT_EQ(status("/files/" + dir_ + "/secret.txt"), 403);
}

TEST_F(StudioServerTest, AnswersOnlyToItsOwnNames) {
  start();
  EXPECT_EQ(status("/api/state", {{"Host", "attacker.example:" + std::to_string(port_)}}), 403);
  EXPECT_EQ(status("/api/state", {{"Host", "localhost:" + std::to_string(port_)}}), 200);
}

TEST_F(StudioServerTest, WithATokenEveryRequestMustCarryIt) {
  start("0123456789abcdef0123456789abcdef");
  EXPECT_EQ(status("/api/state"), 403);
  EXPECT_EQ(status("/?token=wrong"), 403);
  httplib::Client client("127.0.0.1", port_);
  const httplib::Result page = client.Get("/?token=0123456789abcdef0123456789abcdef");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  // The page's later requests carry it as a cookie.
  const std::string cookie = page->get_header_value("Set-Cookie");
  EXPECT_NE(cookie.find("sylva_token=0123456789abcdef0123456789abcdef"), std::string::npos);
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos);
  EXPECT_EQ(status("/api/state", {{"Cookie", "sylva_token=0123456789abcdef0123456789abcdef"}}), 200);
  EXPECT_EQ(status("/api/state", {{"X-Sylva-Token", "0123456789abcdef0123456789abcdef"}}), 200);
}

TEST(StudioToken, IsThirtyTwoHexDigitsAndNeverTheSameTwice) {
  const std::string a = make_token(), b = make_token();
  EXPECT_EQ(a.size(), 32u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace sylva::studio
