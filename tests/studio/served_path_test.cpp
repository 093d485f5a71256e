// Which file of the model's folder a URL path may read.
#include <gtest/gtest.h>

#include <fstream>

#include "studio/served_path.h"
#include "test_support.h"

namespace sylva::studio {
namespace {

namespace fs = std::filesystem;

class ServedPath : public ::testing::Test {
 protected:
  void SetUp() override {
    const fs::path base = test::make_temp_dir("served-path");
    folder_ = base / "model";
    outside_ = base / "outside";
    fs::create_directories(folder_ / "sub");
    fs::create_directories(outside_);
    std::ofstream(folder_ / "plant.l") << "Lsystem: 1\n";
    std::ofstream(folder_ / "sub" / "x.txt") << "x\n";
    std::ofstream(outside_ / "secret.txt") << "secret\n";
    fs::create_symlink(folder_ / "plant.l", folder_ / "link_in");
    fs::create_symlink("../outside/secret.txt", folder_ / "link_out");
    fs::create_symlink(outside_, folder_ / "escape");
  }

  std::optional<fs::path> served(std::string_view request) const { return served_path(folder_, request); }

  fs::path folder_;
  fs::path outside_;
};

TEST_F(ServedPath, FilesInsideTheFolderAreServedByTheirCanonicalPath) {
  const fs::path plant = fs::canonical(folder_ / "plant.l");
  EXPECT_EQ(served("plant.l"), plant);
  EXPECT_EQ(served("./plant.l"), plant);
  EXPECT_EQ(served("sub//x.txt"), fs::canonical(folder_ / "sub" / "x.txt"));
  EXPECT_EQ(served("link_in"), plant);  // a link that stays inside
}

TEST_F(ServedPath, NothingOutsideTheFolderNorWhatIsNotAFile) {
  EXPECT_EQ(served("link_out"), std::nullopt);
  EXPECT_EQ(served("escape/secret.txt"), std::nullopt);
  EXPECT_EQ(served("../outside/secret.txt"), std::nullopt);
  EXPECT_EQ(served("sub/../plant.l"), std::nullopt);  // ".." refused even when it stays inside
  EXPECT_EQ(served((outside_ / "secret.txt").string()), std::nullopt);
  EXPECT_EQ(served((folder_ / "plant.l").string()), std::nullopt);  // absolute
  EXPECT_EQ(served(""), std::nullopt);
  EXPECT_EQ(served("sub"), std::nullopt);
  EXPECT_EQ(served("missing.l"), std::nullopt);
  EXPECT_EQ(served(std::string_view("plant.l\0x", 9)), std::nullopt);
}

TEST_F(ServedPath, AFolderReachedThroughALinkIsItsRealPath) {
  const fs::path linked = folder_.parent_path() / "linked-model";
  fs::create_symlink(folder_, linked);
  EXPECT_EQ(served_path(linked, "plant.l"), fs::canonical(folder_ / "plant.l"));
}

}  // namespace
}  // namespace sylva::studio
