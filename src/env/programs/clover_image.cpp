#include "env/programs/clover_image.h"

#include <fstream>
#include <iterator>
#include <stdexcept>

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

GreenChannel read_green_channel(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the file");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels =
      stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 3);
  if (!pixels) throw std::runtime_error(std::string("not an image that can be read: ") + stbi_failure_reason());
  GreenChannel image;
  image.width = width;
  image.height = height;
  image.values.resize(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < image.values.size(); ++i) image.values[i] = pixels[3 * i + 1] / 255.0f;
  stbi_image_free(pixels);
  return image;
}

}  // namespace sylva::env
