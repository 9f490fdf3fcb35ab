// Whole tiles between the framebuffer and a tile buffer (raster.hpp's load_tile and
// store_tile), with the widest vectors the CPU has. Draws nothing.
// Compiled once per SIMD target (Highway), chosen at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/tile_io.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include <cstdint>
#include <cstring>

#include "fast/raster.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void LoadTile(TileBuffer& b, const TileRows& from, std::uint8_t clear, std::uint32_t clear_color, float clear_depth,
              bool with_depth) {
  const hn::ScalableTag<std::uint32_t> du;
  const hn::ScalableTag<float> df;
  const std::size_t n = hn::Lanes(du);
  const bool color = clear & PipelineContext::PendingClears::kColor, depth = clear & PipelineContext::PendingClears::kDepth;
  const auto cv = hn::Set(du, clear_color);
  const auto dv = hn::Set(df, clear_depth);
  for (int r = 0; r < kTileSize; ++r) {
    std::uint32_t* c = b.color + r * kTileSize;
    float* d = b.depth + r * kTileSize;
    const std::size_t row = std::size_t(r) * from.stride;
    if (color) {
      for (std::size_t i = 0; i < kTileSize; i += n) hn::Store(cv, du, c + i);
    } else {
      for (std::size_t i = 0; i < kTileSize; i += n) hn::Store(hn::LoadU(du, from.color + row + i), du, c + i);
    }
    if (!with_depth) continue;
    if (depth) {
      for (std::size_t i = 0; i < kTileSize; i += n) hn::Store(dv, df, d + i);
    } else {
      for (std::size_t i = 0; i < kTileSize; i += n) hn::Store(hn::LoadU(df, from.depth + row + i), df, d + i);
    }
  }
}

// One row of a tile written out with streaming stores (dst on 16 bytes): whole vectors where
// dst is aligned to them, 16-byte ones (or fewer lanes) at the ends.
template <class D, typename T>
HWY_INLINE void stream_row(D d, T* dst, const T* src) {
  const hn::CappedTag<T, 16 / sizeof(T)> d4;
  const std::size_t n = hn::Lanes(d), n4 = hn::Lanes(d4);
  const std::size_t misaligned = (reinterpret_cast<std::uintptr_t>(dst) / sizeof(T)) % n;
  std::size_t i = 0;
  for (; i < (misaligned ? n - misaligned : 0); i += n4) hn::Stream(hn::LoadU(d4, src + i), d4, dst + i);
  for (; i + n <= std::size_t(kTileSize); i += n) hn::Stream(hn::LoadU(d, src + i), d, dst + i);
  for (; i < std::size_t(kTileSize); i += n4) hn::Stream(hn::LoadU(d4, src + i), d4, dst + i);
}

void StoreTile(const TileBuffer& b, const TileRows& to, bool with_depth) {
  const hn::ScalableTag<std::uint32_t> du;
  const hn::ScalableTag<float> df;
  const bool aligned = (reinterpret_cast<std::uintptr_t>(to.color) | reinterpret_cast<std::uintptr_t>(to.depth) |
                        to.stride * sizeof(float)) % 16 == 0;
  for (int r = 0; r < kTileSize; ++r) {
    const std::size_t row = std::size_t(r) * to.stride;
    if (aligned) {
      stream_row(du, to.color + row, b.color + r * kTileSize);
      if (with_depth) stream_row(df, to.depth + row, b.depth + r * kTileSize);
    } else {
      std::memcpy(to.color + row, b.color + r * kTileSize, kTileSize * sizeof(std::uint32_t));
      if (with_depth) std::memcpy(to.depth + row, b.depth + r * kTileSize, kTileSize * sizeof(float));
    }
  }
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab::fast {

HWY_EXPORT(LoadTile);
HWY_EXPORT(StoreTile);

void load_tile(TileBuffer& b, const TileRows& from, std::uint8_t clear, std::uint32_t clear_color,
               float clear_depth, bool with_depth) {
  HWY_DYNAMIC_DISPATCH(LoadTile)(b, from, clear, clear_color, clear_depth, with_depth);
}

void store_tile(const TileBuffer& b, const TileRows& to, bool with_depth) {
  HWY_DYNAMIC_DISPATCH(StoreTile)(b, to, with_depth);
}

}  // namespace shadelab::fast
#endif
