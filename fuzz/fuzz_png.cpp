// Texture images: any bytes through the image reader; a decoded image becomes a texture
// with its mipmaps, as the scene reader does.
#include <cstdint>
#include <string>

#include "fuzz_util.hpp"
#include "shadelab/image.hpp"
#include "shadelab/texture.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string path = shadelab::fuzz::write_input("input.png", data, size);
  shadelab::Image image;
  std::string error;
  // The header's size is checked before decoding (a few bytes can declare gigapixels).
  if (!shadelab::read_image(path, image, &error, 4096)) return 0;
  if (image.width <= 0 || image.height <= 0) __builtin_trap();
  if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) __builtin_trap();
  shadelab::Texture texture;
  shadelab::TextureLevel level;
  level.width = image.width;
  level.height = image.height;
  level.rgba = image.rgba;
  texture.levels.push_back(std::move(level));
  shadelab::generate_mipmaps(texture);
  return 0;
}
