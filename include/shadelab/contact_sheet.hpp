// Text drawn with a TrueType font (stb_truetype) and contact sheets: images laid out in a
// grid with a label under each, like the lecture's rows of pictures. Never prints.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shadelab/image.hpp"

namespace shadelab {

/// A TrueType font loaded from a file. The default is DejaVu Sans from Debian's
/// fonts-dejavu-core package.
class Font {
 public:
  static constexpr const char* kDefaultPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  /// Loads the font; on failure returns nullptr and sets `error`.
  static std::unique_ptr<Font> load(const std::string& path, std::string* error);
  ~Font();

  /// Width in pixels of `text` (UTF-8) at `pixel_height`.
  int text_width(const std::string& text, float pixel_height) const;
  /// Draws `text` with its top-left corner at (x, y) (image pixels, y down), blended over
  /// the image in `rgb`.
  void draw(Image& image, int x, int y, const std::string& text, float pixel_height,
            const unsigned char rgb[3]) const;

 private:
  Font() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct SheetCell {
  Image image;
  std::string label;  ///< e.g. "cutoff = 50"
};

/// Lays `cells` out left to right, top to bottom, `columns` per row, each with its label
/// centred underneath, on a white sheet; an optional title spans the top.
Image make_contact_sheet(const std::vector<SheetCell>& cells, int columns, const Font& font,
                         const std::string& title = "");

}  // namespace shadelab
