// Bezier evaluation for the evaluators (GL 1.1 section 5.1): points of curves and tensor-product
// surfaces, and a surface point with its two tangent directions for GL_AUTO_NORMAL. In single
// precision, in the order of operations Mesa uses (Horner's scheme for points, de Casteljau's
// for tangents), so that evaluated vertices round as Mesa's do. Pure functions, no GL state.
#pragma once

namespace shadelab::gl {

/// The point at t in [0, 1] of the Bezier curve of `order` control points of `dim` floats
/// each, `stride` floats apart.
void bezier_curve(const float* points, int stride, int dim, int order, float t, float* out);

/// The point at (u, v) of the tensor-product Bezier surface whose control point (i, j) is at
/// points[(i * vorder + j) * dim].
void bezier_surface(const float* points, int dim, int uorder, int vorder, float u, float v,
                    float* out);

/// The same point by de Casteljau's construction, with the directions of the partial
/// derivatives in u and v (not scaled by the orders: only their directions are used). A
/// direction along which the surface has one control point is zero.
void bezier_surface_tangents(const float* points, int dim, int uorder, int vorder, float u, float v,
                             float* out, float* du, float* dv);

}  // namespace shadelab::gl
