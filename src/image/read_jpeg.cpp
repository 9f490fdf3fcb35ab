// JPEG files through libjpeg-turbo (the jpeglib.h API), into 8-bit RGBA. Its errors come back
// through an error manager that jumps back to the decoder instead of exiting; its warnings
// (corrupt data it can decode past) are dropped, as stb_image ignored them before, except the
// end of the file before the image's end: that is an error. A progressive file may take at
// most kMaxScans scans, libjpeg-turbo's own guard against files made to decode for ever.
#include <algorithm>
#include <csetjmp>
#include <cstddef>

// jpeglib.h needs FILE and size_t declared before it.
// clang-format off
#include <stdio.h>
#include <jpeglib.h>
#include <jerror.h>
// clang-format on

#include "image/decoders.hpp"

namespace shadelab::detail {

namespace {

constexpr int kMaxScans = 500;  // libjpeg-turbo's TJFLAG_LIMITSCANS and djpeg -maxscans

struct JpegErrors {
  jpeg_error_mgr manager;  // first: libjpeg's callbacks get its address, which is ours
  jpeg_progress_mgr progress;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX + 64] = "";
};

JpegErrors& errors_of(j_common_ptr cinfo) { return *reinterpret_cast<JpegErrors*>(cinfo->err); }

[[noreturn]] void stop(j_common_ptr cinfo, const char* prefix, const char* message) {
  JpegErrors& e = errors_of(cinfo);
  std::snprintf(e.message, sizeof e.message, "%s%s", prefix, message);
  std::longjmp(e.jump, 1);
}

[[noreturn]] void on_error(j_common_ptr cinfo) {
  char text[JMSG_LENGTH_MAX];
  (*cinfo->err->format_message)(cinfo, text);
  stop(cinfo, "invalid JPEG: ", text);
}

// Level -1 is a warning; the others are trace messages. jpeg_stdio_src warns JWRN_JPEG_EOF
// when the file ends and would go on with an invented end of image.
void on_message(j_common_ptr cinfo, int level) {
  if (level < 0 && cinfo->err->msg_code == JWRN_JPEG_EOF)
    stop(cinfo, "", "the JPEG file is truncated");
}

void no_output(j_common_ptr) {}

void on_progress(j_common_ptr cinfo) {
  auto* d = reinterpret_cast<j_decompress_ptr>(cinfo);
  if (d->input_scan_number > kMaxScans) {
    char text[96];
    std::snprintf(text, sizeof text, "the JPEG file has more than %d scans, the most read",
                  kMaxScans);
    stop(cinfo, "", text);
  }
}

// Called after setjmp: the decompressor over `file`, its markers read up to the first scan.
void read_header(jpeg_decompress_struct& cinfo, JpegErrors& errors, std::FILE* file) {
  cinfo.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = on_error;
  errors.manager.emit_message = on_message;
  errors.manager.output_message = no_output;
  jpeg_create_decompress(&cinfo);
  errors.progress.progress_monitor = on_progress;
  cinfo.progress = &errors.progress;
  jpeg_stdio_src(&cinfo, file);
  jpeg_read_header(&cinfo, TRUE);
}

// Adobe's CMYK (and YCCK, which libjpeg turns into CMYK) is stored inverted: 255 is no ink.
// R = C K / 255, rounded (C, K as stored); the same for G with M and B with Y.
void cmyk_to_rgba(std::uint8_t* p, int width) {
  for (int x = 0; x < width; ++x, p += 4) {
    const int k = p[3];
    for (int c = 0; c < 3; ++c) p[c] = std::uint8_t((p[c] * k + 127) / 255);
    p[3] = 255;
  }
}

// Scanline by scanline into `out`, whose memory is reserved but filled only as rows come.
void read_rows(jpeg_decompress_struct& cinfo, bool cmyk, Image& out) {
  const std::size_t row_bytes = std::size_t(out.width) * 4;
  if (!reserve_pixels(out, row_bytes * std::size_t(out.height))) {
    stop(reinterpret_cast<j_common_ptr>(&cinfo), "", "not enough memory for the image");
  }
  while (cinfo.output_scanline < cinfo.output_height) {
    const int y = int(cinfo.output_scanline);
    out.rgba.resize(row_bytes * std::size_t(y + 1));  // within the reserved capacity
    JSAMPROW row = out.pixel(0, y);
    jpeg_read_scanlines(&cinfo, &row, 1);
    if (cmyk) cmyk_to_rgba(row, out.width);
  }
}

}  // namespace

bool jpeg_header_size(std::FILE* file, std::uint32_t& width, std::uint32_t& height,
                      std::string& error) {
  jpeg_decompress_struct cinfo{};  // zeroed: jpeg_destroy_decompress may come before create
  JpegErrors errors;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&cinfo);
    error = errors.message;
    return false;
  }
  read_header(cinfo, errors, file);
  width = cinfo.image_width;
  height = cinfo.image_height;
  jpeg_destroy_decompress(&cinfo);
  return true;
}

bool decode_jpeg(std::FILE* file, int max_side, Image& out, std::string& error) {
  jpeg_decompress_struct cinfo{};
  JpegErrors errors;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&cinfo);
    error = errors.message;
    out = Image{};
    return false;
  }
  read_header(cinfo, errors, file);
  if (cinfo.image_width > JDIMENSION(std::max(max_side, 1)) ||
      cinfo.image_height > JDIMENSION(std::max(max_side, 1))) {
    stop(reinterpret_cast<j_common_ptr>(&cinfo), "", "the image is larger than the limit");
  }
  const bool cmyk = cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK;
  cinfo.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;  // libjpeg-turbo's RGBA: alpha 255
  jpeg_start_decompress(&cinfo);
  out = Image{};
  out.width = int(cinfo.output_width);
  out.height = int(cinfo.output_height);
  read_rows(cinfo, cmyk, out);
  jpeg_finish_decompress(&cinfo);  // the rest of the file up to the end of image marker
  jpeg_destroy_decompress(&cinfo);
  return true;
}

}  // namespace shadelab::detail
