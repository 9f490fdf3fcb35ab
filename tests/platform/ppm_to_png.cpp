// Converts a binary PPM (P6, 8-bit), as the platform tests' GL programs write with glReadPixels,
// into an opaque PNG for gl_compare.   ppm_to_png IN.ppm OUT.png
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "shadelab/image.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: ppm_to_png IN.ppm OUT.png\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::string magic;
  int width = 0, height = 0, max = 0;
  in >> magic >> width >> height >> max;
  in.get();  // the single whitespace before the pixels
  if (!in || magic != "P6" || max != 255 || width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    std::cerr << "ppm_to_png: " << argv[1] << ": not an 8-bit binary PPM\n";
    return 1;
  }
  shadelab::Image image{width, height, {}};
  image.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
  for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i) {
    char rgb[3];
    if (!in.read(rgb, 3)) {
      std::cerr << "ppm_to_png: " << argv[1] << ": truncated\n";
      return 1;
    }
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + std::size_t(c)] = static_cast<unsigned char>(rgb[c]);
    image.rgba[i * 4 + 3] = 255;
  }
  std::string error;
  if (!shadelab::write_png(image, argv[2], &error)) {
    std::cerr << "ppm_to_png: " << error << "\n";
    return 1;
  }
  return 0;
}
