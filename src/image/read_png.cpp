// PNG files through libpng, into 8-bit RGBA: 16-bit samples keep their high byte, palette and
// grey images are expanded, tRNS becomes alpha, interlaced images come out whole (the bytes
// stb_image gave before for every valid file). libpng's limits are set here, not left to how it
// was built; its errors come back through the error callback and a longjmp, its warnings are
// dropped (the library never prints).
#include <algorithm>
#include <csetjmp>
#include <cstddef>
#include <new>
#include <vector>

#include <png.h>

#include "image/decoders.hpp"

namespace shadelab::detail {

namespace {

// The most bytes libpng may allocate for one chunk (every chunk but IDAT, which it reads a few
// kilobytes at a time as it inflates it, whatever length the chunk declares). Only IHDR, PLTE
// and tRNS are kept, none over 768 bytes; this is libpng's own default, fixed here.
constexpr png_alloc_size_t kChunkMallocMax = 8'000'000;
// The most ancillary chunks libpng keeps (text, sPLT, unknown); none is kept here anyway.
constexpr png_uint_32 kChunkCacheMax = 128;

struct PngInput {
  std::FILE* file;
  char message[256] = "";  // why decoding stopped (written without allocating)
};

[[noreturn]] void stop(png_structp png, const char* prefix, const char* message) {
  auto* in = static_cast<PngInput*>(png_get_error_ptr(png));
  std::snprintf(in->message, sizeof in->message, "%s%s", prefix, message);
  png_longjmp(png, 1);
}

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  stop(png, "invalid PNG: ", message);
}

void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep data, std::size_t length) {
  auto* in = static_cast<PngInput*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, in->file) != length) stop(png, "", "the PNG file is truncated");
}

// libpng's input transformations to 8-bit RGBA (its manual, "Transformations"). Returns the
// number of passes png_read_row takes (7 for an interlaced image, else 1).
int ask_for_rgba8(png_structp png, png_infop info) {
  const png_byte type = png_get_color_type(png, info);
  const png_byte depth = png_get_bit_depth(png, info);
  if (depth == 16) png_set_strip_16(png);
  if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if ((type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(png);
  png_set_filler(png, 0xff, PNG_FILLER_AFTER);  // opaque where the image has no alpha
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return passes;
}

// The rows of an interlaced image: every pass writes into all of them.
bool all_rows(Image& out, std::vector<png_bytep>& rows) noexcept {
  try {
    out.rgba.resize(std::size_t(out.width) * 4 * std::size_t(out.height));
    rows.resize(std::size_t(out.height));
  } catch (const std::bad_alloc&) {
    return false;
  }
  for (int y = 0; y < out.height; ++y) rows[std::size_t(y)] = out.pixel(0, y);
  return true;
}

void read_rows(png_structp png, int passes, Image& out, std::vector<png_bytep>& rows) {
  const std::size_t row_bytes = std::size_t(out.width) * 4;
  if (!reserve_pixels(out, row_bytes * std::size_t(out.height))) {
    stop(png, "", "not enough memory for the image");
  }
  if (passes > 1) {
    if (!all_rows(out, rows)) stop(png, "", "not enough memory for the image");
    png_read_image(png, rows.data());
    return;
  }
  for (int y = 0; y < out.height; ++y) {
    out.rgba.resize(row_bytes * std::size_t(y + 1));  // within the reserved capacity
    png_read_row(png, out.pixel(0, y), nullptr);
  }
}

}  // namespace

bool png_header_size(const std::uint8_t (&first)[24], std::uint32_t& width, std::uint32_t& height) {
  static const std::uint8_t kIhdr[8] = {0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  if (!std::equal(kIhdr, kIhdr + 8, first + 8)) return false;
  width = png_get_uint_32(first + 16);
  height = png_get_uint_32(first + 20);
  return width >= 1 && height >= 1 && width <= PNG_UINT_31_MAX && height <= PNG_UINT_31_MAX;
}

bool decode_png(std::FILE* file, int max_side, Image& out, std::string& error) {
  PngInput in{file};
  std::vector<png_bytep> rows;  // made before setjmp: nothing is left for a longjmp to skip
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &in, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info || setjmp(png_jmpbuf(png))) {
    error = info ? in.message : "not enough memory for the PNG decoder";
    png_destroy_read_struct(&png, &info, nullptr);
    out = Image{};
    return false;
  }
  png_set_read_fn(png, &in, read_bytes);
  const auto side = png_uint_32(std::max(max_side, 1));
  png_set_user_limits(png, side, side);
  png_set_chunk_malloc_max(png, kChunkMallocMax);
  png_set_chunk_cache_max(png, kChunkCacheMax);
  // Every chunk but IHDR, PLTE, tRNS, IDAT and IEND is skipped unread (CRC still checked):
  // text, colour profiles and the like do not change the bytes read here.
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);
  png_read_info(png, info);
  const int passes = ask_for_rgba8(png, info);
  out = Image{};
  out.width = int(png_get_image_width(png, info));
  out.height = int(png_get_image_height(png, info));
  if (png_get_rowbytes(png, info) != std::size_t(out.width) * 4)
    png_error(png, "no RGBA conversion");
  read_rows(png, passes, out, rows);
  png_read_end(png, nullptr);  // the rest of the file up to IEND, CRCs checked
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace shadelab::detail
