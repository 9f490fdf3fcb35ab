// Animated PNG (the APNG specification: acTL, fcTL and fdAT chunks around an ordinary PNG).
// Debian's libpng has no APNG support, so each frame is encoded as a PNG by libpng
// (encode_png) and its chunks rearranged: the first frame's IDAT chunks stay the default
// image, the others' become fdAT chunks, and every frame gets its frame control chunk.
#include <zlib.h>

#include <cstring>

#include "shadelab/image.hpp"

namespace shadelab {

namespace {

struct Chunk {
  std::string type;
  const std::uint8_t* data;
  std::size_t size;
};

std::uint32_t read_be32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

void put_be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

void put_be16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(std::uint8_t(v >> 8));
  out.push_back(std::uint8_t(v));
}

// A PNG's chunks after its signature (libpng's own output: well formed).
std::vector<Chunk> chunks_of(const std::vector<std::uint8_t>& png) {
  std::vector<Chunk> out;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t size = read_be32(&png[at]);
    if (at + 12 + size > png.size()) break;
    out.push_back({std::string(reinterpret_cast<const char*>(&png[at + 4]), 4), &png[at + 8], size});
    at += 12 + size;
  }
  return out;
}

void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& body) {
  put_be32(out, std::uint32_t(body.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), body.begin(), body.end());
  put_be32(out, std::uint32_t(crc32(0, &out[start], uInt(out.size() - start))));
}

// The frame control chunk of a whole-picture frame.
std::vector<std::uint8_t> frame_control(std::uint32_t sequence, const Image& f, int delay_num, int delay_den) {
  std::vector<std::uint8_t> b;
  put_be32(b, sequence);
  put_be32(b, std::uint32_t(f.width));
  put_be32(b, std::uint32_t(f.height));
  put_be32(b, 0);  // x offset
  put_be32(b, 0);  // y offset
  put_be16(b, std::uint16_t(delay_num));
  put_be16(b, std::uint16_t(delay_den));
  b.push_back(0);  // dispose: none
  b.push_back(0);  // blend: source (the frame replaces what was there)
  return b;
}

}  // namespace

std::vector<std::uint8_t> encode_apng(const std::vector<Image>& frames, int delay_num, int delay_den, int plays) {
  if (frames.empty() || delay_num < 0 || delay_num > 65535 || delay_den < 0 || delay_den > 65535 || plays < 0) {
    return {};
  }
  for (const Image& f : frames) {
    if (f.width <= 0 || f.height <= 0 || f.width != frames[0].width || f.height != frames[0].height) return {};
  }
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::uint32_t sequence = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::vector<std::uint8_t> png = encode_png(frames[i]);
    if (png.empty()) return {};
    const std::vector<Chunk> chunks = chunks_of(png);
    if (i == 0) {
      for (const Chunk& c : chunks) {
        if (c.type != "IHDR") continue;
        put_chunk(out, "IHDR", std::vector<std::uint8_t>(c.data, c.data + c.size));
      }
      std::vector<std::uint8_t> actl;
      put_be32(actl, std::uint32_t(frames.size()));
      put_be32(actl, std::uint32_t(plays));
      put_chunk(out, "acTL", actl);
    }
    put_chunk(out, "fcTL", frame_control(sequence++, frames[i], delay_num, delay_den));
    for (const Chunk& c : chunks) {
      if (c.type != "IDAT") continue;
      if (i == 0) {
        put_chunk(out, "IDAT", std::vector<std::uint8_t>(c.data, c.data + c.size));
      } else {
        std::vector<std::uint8_t> body;
        put_be32(body, sequence++);
        body.insert(body.end(), c.data, c.data + c.size);
        put_chunk(out, "fdAT", body);
      }
    }
  }
  put_chunk(out, "IEND", {});
  return out;
}

bool write_apng(const std::vector<Image>& frames, const std::string& path, int delay_num, int delay_den,
                std::string* error) {
  std::vector<std::uint8_t> bytes = encode_apng(frames, delay_num, delay_den);
  if (bytes.empty()) {
    if (error) *error = "cannot make an animated PNG of these frames (none, or of different sizes)";
    return false;
  }
  return write_file_atomically(bytes, path, error);
}

}  // namespace shadelab
