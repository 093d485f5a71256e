#include "env/programs/sgi_image.h"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace sylva::env {
namespace {

constexpr std::uint16_t kMagic = 0x01DA;
constexpr std::size_t kHeaderSize = 512;

// Reads big-endian numbers, or little-endian ones when the file was written
// on such a machine (its magic number reads swapped).
class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, bool swapped) : bytes_(bytes), swapped_(swapped) {}

  std::uint16_t u16(std::size_t at) const {
    need(at, 2);
    return swapped_ ? static_cast<std::uint16_t>(bytes_[at] | bytes_[at + 1] << 8)
                    : static_cast<std::uint16_t>(bytes_[at] << 8 | bytes_[at + 1]);
  }
  std::uint32_t u32(std::size_t at) const {
    need(at, 4);
    std::uint32_t value = 0;
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t byte = bytes_[at + static_cast<std::size_t>(swapped_ ? 3 - k : k)];
      value = value << 8 | byte;
    }
    return value;
  }
  void need(std::size_t at, std::size_t count) const {
    if (at > bytes_.size() || count > bytes_.size() - at)
      throw std::runtime_error("the SGI image ends early (at byte " + std::to_string(bytes_.size()) + ")");
  }

 private:
  const std::vector<std::uint8_t>& bytes_;
  bool swapped_;
};

// One run-length encoded row: a count byte (low 7 bits; 0 ends the row)
// followed by that many literal bytes when its high bit is set, else by one
// byte repeated that many times.
void decode_rle_row(const std::vector<std::uint8_t>& bytes, const Reader& reader, std::size_t at, std::size_t size,
                    std::uint8_t* out, int width) {
  reader.need(at, size);
  const std::size_t end = at + size;
  int x = 0;
  while (at < end) {
    const std::uint8_t control = bytes[at++];
    int count = control & 0x7F;
    if (count == 0) return;
    if (control & 0x80) {
      while (count-- > 0 && at < end && x < width) out[x++] = bytes[at++];
    } else {
      if (at >= end) return;
      const std::uint8_t value = bytes[at++];
      while (count-- > 0 && x < width) out[x++] = value;
    }
  }
}

}  // namespace

bool looks_like_sgi_image(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < 2) return false;
  const std::uint16_t magic = static_cast<std::uint16_t>(bytes[0] << 8 | bytes[1]);
  return magic == kMagic || magic == 0xDA01;
}

SgiImage decode_sgi_image(const std::vector<std::uint8_t>& bytes) {
  if (!looks_like_sgi_image(bytes)) throw std::runtime_error("not an SGI image (no magic number 474)");
  const bool swapped = bytes[0] == 0xDA;
  const Reader reader(bytes, swapped);
  const std::uint16_t type = reader.u16(2);
  SgiImage image;
  image.width = reader.u16(6);
  image.height = reader.u16(8);
  image.channels = reader.u16(10);
  const std::uint16_t dimension = reader.u16(4);
  if (dimension < 3) image.channels = 1;  // the z size is meaningful in 3-D images only
  if (dimension < 2) image.height = 1;
  if (image.width == 0 || image.height == 0 || image.channels == 0)
    throw std::runtime_error("the SGI image has no pixels");
  const std::size_t rows = static_cast<std::size_t>(image.height) * image.channels;
  image.values.assign(rows * image.width, 0);
  if ((type & 0xFF00) == 0x0100) {
    const std::size_t starts = kHeaderSize, sizes = kHeaderSize + 4 * rows;
    for (std::size_t row = 0; row < rows; ++row)
      decode_rle_row(bytes, reader, reader.u32(starts + 4 * row), reader.u32(sizes + 4 * row),
                     image.values.data() + row * image.width, image.width);
  } else {
    reader.need(kHeaderSize, rows * image.width);
    std::copy(bytes.begin() + kHeaderSize, bytes.begin() + static_cast<std::ptrdiff_t>(kHeaderSize + rows * image.width),
              image.values.begin());
  }
  return image;
}

}  // namespace sylva::env
