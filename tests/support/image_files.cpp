// Implementation of the test image files (see image_files.hpp).
#include "support/image_files.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

// jpeglib.h needs FILE and size_t declared before it.
// clang-format off
#include <stdio.h>
#include <jpeglib.h>
// clang-format on
#include <png.h>

#include "support/test_support.hpp"

namespace shadelab::test {

namespace {

void append(png_structp png, png_bytep data, std::size_t length) {
  auto* out = static_cast<Bytes*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

void set_transparency(png_structp png, png_infop info, const PngSpec& s) {
  png_color_16 colour{};
  if (!s.palette_alpha.empty()) {
    png_set_tRNS(png, info, s.palette_alpha.data(), int(s.palette_alpha.size()), nullptr);
  } else if (s.transparent_grey) {
    colour.gray = *s.transparent_grey;
    png_set_tRNS(png, info, nullptr, 0, &colour);
  } else if (s.transparent_rgb[0]) {
    colour.red = *s.transparent_rgb[0];
    colour.green = *s.transparent_rgb[1];
    colour.blue = *s.transparent_rgb[2];
    png_set_tRNS(png, info, nullptr, 0, &colour);
  }
}

struct JpegFailure {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
};

[[noreturn]] void jpeg_failed(j_common_ptr cinfo) {
  std::longjmp(reinterpret_cast<JpegFailure*>(cinfo->err)->jump, 1);
}

}  // namespace

Bytes encode_png_file(const PngSpec& s) {
  Bytes out;
  std::vector<png_bytep> rows;
  for (const Bytes& row : s.rows) rows.push_back(const_cast<png_bytep>(row.data()));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return {};
  }
  png_set_write_fn(png, &out, append, no_flush);
  png_set_IHDR(png, info, png_uint_32(s.width), png_uint_32(s.height), s.bit_depth, s.color_type,
               s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette;
  for (std::size_t i = 0; i + 2 < s.palette.size(); i += 3) {
    palette.push_back({s.palette[i], s.palette[i + 1], s.palette[i + 2]});
  }
  if (!palette.empty()) png_set_PLTE(png, info, palette.data(), int(palette.size()));
  set_transparency(png, info, s);
  png_write_info(png, info);
  png_write_image(png, rows.data());  // each Adam7 pass, when interlaced
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

Bytes encode_jpeg_file(int width, int height, int components, const Bytes& samples,
                       bool progressive, bool ycck) {
  jpeg_compress_struct cinfo{};
  JpegFailure failure;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  cinfo.err = jpeg_std_error(&failure.manager);
  failure.manager.error_exit = jpeg_failed;
  if (setjmp(failure.jump)) {
    jpeg_destroy_compress(&cinfo);
    std::free(buffer);
    return {};
  }
  jpeg_create_compress(&cinfo);
  jpeg_mem_dest(&cinfo, &buffer, &size);
  cinfo.image_width = JDIMENSION(width);
  cinfo.image_height = JDIMENSION(height);
  cinfo.input_components = components;
  cinfo.in_color_space = components == 1 ? JCS_GRAYSCALE : components == 3 ? JCS_RGB : JCS_CMYK;
  jpeg_set_defaults(&cinfo);
  if (ycck) jpeg_set_colorspace(&cinfo, JCS_YCCK);
  jpeg_set_quality(&cinfo, 100, TRUE);
  for (int c = 0; c < cinfo.num_components; ++c) {
    cinfo.comp_info[c].h_samp_factor = cinfo.comp_info[c].v_samp_factor = 1;
  }
  if (progressive) jpeg_simple_progression(&cinfo);
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row =
        const_cast<JSAMPROW>(&samples[std::size_t(cinfo.next_scanline) * width * components]);
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  Bytes out(buffer, buffer + size);
  jpeg_destroy_compress(&cinfo);
  std::free(buffer);
  return out;
}

Bytes encode_many_scans_jpeg_file() {
  jpeg_compress_struct cinfo{};
  JpegFailure failure;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  std::vector<jpeg_scan_info> scans(1, jpeg_scan_info{1, {0}, 0, 0, 0, 0});  // DC, whole
  for (int k = 1; k <= 63; ++k) {
    scans.push_back({1, {0}, k, k, 0, 9});
    for (int bit = 8; bit >= 0; --bit) scans.push_back({1, {0}, k, k, bit + 1, bit});
  }
  cinfo.err = jpeg_std_error(&failure.manager);
  failure.manager.error_exit = jpeg_failed;
  if (setjmp(failure.jump)) {
    jpeg_destroy_compress(&cinfo);
    std::free(buffer);
    return {};
  }
  jpeg_create_compress(&cinfo);
  jpeg_mem_dest(&cinfo, &buffer, &size);
  cinfo.image_width = cinfo.image_height = 8;
  cinfo.input_components = 1;
  cinfo.in_color_space = JCS_GRAYSCALE;
  jpeg_set_defaults(&cinfo);
  cinfo.scan_info = scans.data();
  cinfo.num_scans = int(scans.size());
  jpeg_start_compress(&cinfo, TRUE);
  std::uint8_t samples[8] = {0, 255, 0, 255, 0, 255, 0, 255};
  for (int y = 0; y < 8; ++y) {
    JSAMPROW row = samples;
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  Bytes out(buffer, buffer + size);
  jpeg_destroy_compress(&cinfo);
  std::free(buffer);
  return out;
}

std::string write_test_file(const std::string& name, const Bytes& bytes) {
  std::filesystem::path dir = std::filesystem::path(output_dir()) / "read_image";
  std::filesystem::create_directories(dir);
  std::string path = (dir / name).string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return path;
}

}  // namespace shadelab::test
