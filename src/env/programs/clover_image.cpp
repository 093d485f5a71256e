#include "env/programs/clover_image.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <string>

#include "env/programs/sgi_image.h"
#include "support/whole_file.h"

// stb_image's functions are compiled into this file only (static), so they
// cannot clash with another copy elsewhere in the program.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace sylva::env {
namespace {

// The image as clover keeps it: two byte planes, row 0 the grid's row 0.
struct Planes {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> light, ratio;

  void resize(int w, int h) {
    width = w;
    height = h;
    light.assign(static_cast<std::size_t>(w) * h, 0);
    ratio.assign(light.size(), 0);
  }
  std::size_t at(int row, int column) const { return static_cast<std::size_t>(row) * width + column; }
};

std::vector<std::uint8_t> file_bytes(const std::filesystem::path& path) {
  const WholeFile file = read_whole_file(path.string());
  if (!file) throw std::runtime_error("cannot read the file");
  return std::vector<std::uint8_t>(file.bytes.begin(), file.bytes.end());
}

// Decodes with stb_image into RGB, top row first.
struct Rgb {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};
Rgb decode_rgb(const std::vector<std::uint8_t>& bytes) {
  Rgb image;
  int channels = 0;
  unsigned char* pixels =
      stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &image.width, &image.height, &channels, 3);
  if (!pixels) throw std::runtime_error(std::string("cannot decode it: ") + stbi_failure_reason());
  image.pixels.assign(pixels, pixels + static_cast<std::size_t>(image.width) * image.height * 3);
  stbi_image_free(pixels);
  return image;
}

// Targa, as clover's own reader takes it: 24-bit true colour (type 2) or
// its run-length encoding (type 10), with the origin at the top left
// (descriptor 0x20) and nothing else. Rows are read in file order into grid
// rows height-1, height-2, ...; of each pixel's three bytes clover keeps the
// third as light and the second as the other value: red and green as the
// file stores them (blue, green, red), but blue and green for the pixels of
// a run, whose colour the reader writes out in reverse.
Planes targa_planes(const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() < 18) throw std::runtime_error("not a Targa image (too short)");
  const int type = bytes[2];
  const int width = bytes[12] | bytes[13] << 8, height = bytes[14] | bytes[15] << 8;
  if ((type != 2 && type != 10) || bytes[16] != 24 || bytes[17] != 0x20)
    throw std::runtime_error("clover reads only 24-bit true-colour Targa images with the origin at the top left");
  std::size_t at = 18 + bytes[0] + (bytes[1] ? static_cast<std::size_t>(bytes[5] | bytes[6] << 8) * 3 : 0);
  auto byte = [&]() -> std::uint8_t { return at < bytes.size() ? bytes[at++] : 0; };
  Planes planes;
  planes.resize(width, height);
  std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 3);
  int left = 0;  // pixels left in the current packet (runs may cross rows)
  bool run = false;
  std::uint8_t colour[3] = {0, 0, 0};
  for (int k = 0; k < height; ++k) {
    if (type == 2) {
      for (std::uint8_t& b : row) b = byte();
    } else {
      for (int x = 0; x < width;) {
        if (left == 0) {
          const std::uint8_t head = byte();
          left = (head & 0x7F) + 1;
          run = (head & 0x80) != 0;
          if (run)
            for (std::uint8_t& c : colour) c = byte();
          continue;
        }
        for (; left > 0 && x < width; --left, ++x)
          for (int c = 0; c < 3; ++c) row[static_cast<std::size_t>(x) * 3 + c] = run ? colour[2 - c] : byte();
      }
    }
    const int y = height - 1 - k;
    for (int x = 0; x < width; ++x) {
      planes.light[planes.at(y, x)] = row[static_cast<std::size_t>(x) * 3 + 2];
      planes.ratio[planes.at(y, x)] = row[static_cast<std::size_t>(x) * 3 + 1];
    }
  }
  return planes;
}

// SGI: rows bottom first, as the grid's.
Planes sgi_planes(const std::vector<std::uint8_t>& bytes) {
  const SgiImage image = decode_sgi_image(bytes);
  Planes planes;
  planes.resize(image.width, image.height);
  // A one-channel image has no channel 1: the real clover reads past its
  // rows; Sylva takes channel 0.
  const int green = std::min(1, image.channels - 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      planes.light[planes.at(y, x)] = image.at(green, y, x);
      planes.ratio[planes.at(y, x)] = image.at(0, y, x);
    }
  return planes;
}

// PNG: rows bottom first; the last row and column are never copied.
Planes png_planes(const std::vector<std::uint8_t>& bytes) {
  static const std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin()))
    throw std::runtime_error("not a PNG image (a name not ending in \"tga\" or \"rgb\" is read as PNG)");
  const Rgb image = decode_rgb(bytes);
  Planes planes;
  planes.resize(image.width, image.height);
  for (int y = 0; y + 1 < image.height; ++y)
    for (int x = 0; x + 1 < image.width; ++x) {
      const std::uint8_t* rgb = &image.pixels[(static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 3];
      planes.light[planes.at(y, x)] = rgb[1];
      planes.ratio[planes.at(y, x)] = rgb[0];
    }
  return planes;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Planes read_planes(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::vector<std::uint8_t> bytes = file_bytes(path);
  if (name.size() > 3 && ends_with(name, "tga")) return targa_planes(bytes);
  if (ends_with(name, "rgb")) return sgi_planes(bytes);
  return png_planes(bytes);
}

// The pixel index clover samples for cell `cell` of `cells` (float, as clover
// computes it).
int sample(int cell, int cells, int pixels) {
  if (cells < 2) return 0;
  const float ratio = static_cast<float>(pixels - 1) / static_cast<float>(cells - 1);
  return std::clamp(static_cast<int>(static_cast<float>(cell) * ratio), 0, pixels - 1);
}

}  // namespace

std::vector<CloverCell> load_clover_ground(const std::filesystem::path& image, std::array<int, 2> size) {
  std::vector<CloverCell> cells(static_cast<std::size_t>(size[0]) * size[1]);
  if (image.empty()) return cells;
  Planes planes;
  try {
    planes = read_planes(image);
  } catch (const std::exception& error) {
    std::cerr << image.string() << ": warning: clover cannot use its input image (" << error.what()
              << "); every cell gets light 0\n";
    for (CloverCell& cell : cells) cell.light = 0;
    return cells;
  }
  for (int y = 0; y < size[1]; ++y) {
    const int row = sample(y, size[1], planes.height);
    for (int x = 0; x < size[0]; ++x) {
      const std::size_t from = planes.at(row, sample(x, size[0], planes.width));
      CloverCell& cell = cells[static_cast<std::size_t>(y) * size[0] + x];
      cell.light = planes.light[from];
      cell.ratio = planes.ratio[from];
    }
  }
  return cells;
}

}  // namespace sylva::env
