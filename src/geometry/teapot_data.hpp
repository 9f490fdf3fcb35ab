// The Utah teapot's control points and patches (see teapot_data.cpp). Private to geometry.
// Data only: teapot.cpp tessellates the patches.
#pragma once

namespace shadelab::detail {

extern const float kTeapotVertices[306][3];  ///< z up, spout toward +x
extern const int kTeapotPatches[32][16];      ///< 1-based indices; row-major 4x4 (u by v)

}  // namespace shadelab::detail
