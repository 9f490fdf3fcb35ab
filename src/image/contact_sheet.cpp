// TrueType text through stb_truetype, and contact sheets (a grid of labelled images).
#include "shadelab/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <stb_truetype.h>

namespace shadelab {

struct Font::Impl {
  std::vector<unsigned char> data;
  stbtt_fontinfo info;
};

Font::~Font() = default;

std::unique_ptr<Font> Font::load(const std::string& path, std::string* error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    if (error) *error = "cannot open font " + path + " (Debian package fonts-dejavu-core)";
    return nullptr;
  }
  std::unique_ptr<Font> font(new Font);
  font->impl_ = std::make_unique<Impl>();
  font->impl_->data.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  const unsigned char* d = font->impl_->data.data();
  if (font->impl_->data.empty() || !stbtt_InitFont(&font->impl_->info, d, stbtt_GetFontOffsetForIndex(d, 0))) {
    if (error) *error = "cannot read font " + path;
    return nullptr;
  }
  return font;
}

namespace {

// Decodes UTF-8 into code points (invalid bytes become U+FFFD).
std::vector<int> code_points(const std::string& s) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.size();) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (len == 0 || i + len > s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    int cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out.push_back(cp);
    i += len;
  }
  return out;
}

}  // namespace

int Font::text_width(const std::string& text, float pixel_height) const {
  float scale = stbtt_ScaleForPixelHeight(&impl_->info, pixel_height);
  float x = 0;
  std::vector<int> cps = code_points(text);
  for (std::size_t i = 0; i < cps.size(); ++i) {
    int advance, lsb;
    stbtt_GetCodepointHMetrics(&impl_->info, cps[i], &advance, &lsb);
    x += advance * scale;
    if (i + 1 < cps.size()) x += scale * stbtt_GetCodepointKernAdvance(&impl_->info, cps[i], cps[i + 1]);
  }
  return int(std::ceil(x));
}

void Font::draw(Image& image, int x, int y, const std::string& text, float pixel_height,
                const unsigned char rgb[3]) const {
  const stbtt_fontinfo* info = &impl_->info;
  float scale = stbtt_ScaleForPixelHeight(info, pixel_height);
  int ascent, descent, gap;
  stbtt_GetFontVMetrics(info, &ascent, &descent, &gap);
  int baseline = y + int(std::lround(ascent * scale));
  float pen = float(x);
  std::vector<int> cps = code_points(text);
  for (std::size_t i = 0; i < cps.size(); ++i) {
    int w, h, xoff, yoff;
    unsigned char* bitmap = stbtt_GetCodepointBitmap(info, scale, scale, cps[i], &w, &h, &xoff, &yoff);
    for (int by = 0; by < h; ++by) {
      for (int bx = 0; bx < w; ++bx) {
        int px = int(pen) + xoff + bx, py = baseline + yoff + by;
        if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
        float a = bitmap[by * w + bx] / 255.0f;
        std::uint8_t* p = image.pixel(px, py);
        for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround(p[c] * (1 - a) + rgb[c] * a));
      }
    }
    stbtt_FreeBitmap(bitmap, nullptr);
    int advance, lsb;
    stbtt_GetCodepointHMetrics(info, cps[i], &advance, &lsb);
    pen += advance * scale;
    if (i + 1 < cps.size()) pen += scale * stbtt_GetCodepointKernAdvance(info, cps[i], cps[i + 1]);
  }
}

Image make_contact_sheet(const std::vector<SheetCell>& cells, int columns, const Font& font,
                         const std::string& title) {
  const int margin = 12, label_height = 26, title_height = title.empty() ? 0 : 36;
  const float label_px = 18.0f, title_px = 24.0f;
  int cell_w = 1, cell_h = 1;
  for (const SheetCell& c : cells) {
    cell_w = std::max(cell_w, c.image.width);
    cell_h = std::max(cell_h, c.image.height);
  }
  columns = std::max(1, std::min<int>(columns, int(std::max<std::size_t>(cells.size(), 1))));
  int rows = int((cells.size() + columns - 1) / columns);
  Image sheet;
  sheet.width = margin + columns * (cell_w + margin);
  sheet.height = margin + title_height + std::max(rows, 1) * (cell_h + label_height + margin);
  sheet.rgba.assign(std::size_t(sheet.width) * sheet.height * 4, 255);
  const unsigned char ink[3] = {20, 20, 20};
  if (!title.empty()) font.draw(sheet, margin, margin / 2, title, title_px, ink);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    int col = int(i % columns), row = int(i / columns);
    int x0 = margin + col * (cell_w + margin);
    int y0 = margin + title_height + row * (cell_h + label_height + margin);
    const Image& img = cells[i].image;
    for (int y = 0; y < img.height; ++y) {
      std::copy_n(img.pixel(0, y), std::size_t(img.width) * 4, sheet.pixel(x0, y0 + y));
    }
    int tw = font.text_width(cells[i].label, label_px);
    font.draw(sheet, x0 + (cell_w - tw) / 2, y0 + cell_h + 3, cells[i].label, label_px, ink);
  }
  return sheet;
}

}  // namespace shadelab
