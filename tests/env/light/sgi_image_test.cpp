// SGI images as the Virtual Laboratory's reader (libs/image) takes them: a
// 512-byte header, big-endian or (magic number swapped) little-endian,
// rows verbatim or run-length encoded, row 0 at the bottom. The files are
// built byte by byte from the format's description.
#include <gtest/gtest.h>

#include <stdexcept>

#include "env/programs/sgi_image.h"

namespace sylva::env {
namespace {

std::vector<std::uint8_t> header(bool little_endian, bool rle, int width, int height, int channels) {
  std::vector<std::uint8_t> bytes(512, 0);
  auto put16 = [&](std::size_t at, int v) {
    bytes[at + (little_endian ? 1 : 0)] = static_cast<std::uint8_t>(v >> 8);
    bytes[at + (little_endian ? 0 : 1)] = static_cast<std::uint8_t>(v);
  };
  put16(0, 474);
  put16(2, (rle ? 1 : 0) << 8 | 1);
  put16(4, 3);
  put16(6, width);
  put16(8, height);
  put16(10, channels);
  return bytes;
}

TEST(SgiImage, VerbatimRowsChannelByChannel) {
  std::vector<std::uint8_t> bytes = header(false, false, 2, 2, 2);
  // Channel 0 rows 0 and 1, then channel 1.
  for (std::uint8_t v : {1, 2, 3, 4, 5, 6, 7, 8}) bytes.push_back(v);
  const SgiImage image = decode_sgi_image(bytes);
  EXPECT_EQ(image.width, 2);
  EXPECT_EQ(image.channels, 2);
  EXPECT_EQ(image.at(0, 0, 1), 2);
  EXPECT_EQ(image.at(0, 1, 0), 3);
  EXPECT_EQ(image.at(1, 1, 1), 8);
}

TEST(SgiImage, RunLengthRowsInALittleEndianFile) {
  std::vector<std::uint8_t> bytes = header(true, true, 4, 1, 1);
  // One row: offset table, length table (little-endian), then a run of three
  // 9s, a literal 7 and the end.
  const std::uint32_t start = 512 + 8, length = 5;
  for (std::uint32_t v : {start, length})
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  for (std::uint8_t v : {0x03, 9, 0x81, 7, 0x00}) bytes.push_back(v);
  const SgiImage image = decode_sgi_image(bytes);
  EXPECT_EQ(image.at(0, 0, 0), 9);
  EXPECT_EQ(image.at(0, 0, 2), 9);
  EXPECT_EQ(image.at(0, 0, 3), 7);
}

TEST(SgiImage, ATruncatedFileIsAnError) {
  std::vector<std::uint8_t> bytes = header(false, false, 4, 4, 3);
  EXPECT_THROW(decode_sgi_image(bytes), std::runtime_error);
  EXPECT_THROW(decode_sgi_image({1, 2, 3}), std::runtime_error);
}

}  // namespace
}  // namespace sylva::env
