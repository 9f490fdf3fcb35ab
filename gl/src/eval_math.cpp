// Bezier evaluation for the evaluators (GL 1.1 section 5.1, equations 5.1-5.3), in single
// precision and in Mesa's order of operations: curves by Horner's scheme on the Bernstein
// form (binomial coefficients built up as (n - i + 1) / i), surfaces as a curve of curves
// (the direction of the higher order last), and GL_AUTO_NORMAL's tangents by de Casteljau's
// construction, which gives the point and both derivative directions at once. No GL state.
#include "gl/src/eval_math.hpp"

#include <algorithm>
#include <vector>

#include "gl/src/eval_state.hpp"

namespace shadelab::gl {
namespace {

// 1 / i for the binomial coefficients, as single-precision reciprocals.
float reciprocal(int i) {
  static const auto table = [] {
    std::array<float, kMaxEvalOrder + 1> t{};
    for (int k = 1; k <= kMaxEvalOrder; ++k) t[k] = 1.0f / float(k);
    return t;
  }();
  return table[i];
}

}  // namespace

void bezier_curve(const float* p, int stride, int dim, int order, float t, float* out) {
  if (order < 2) {
    std::copy_n(p, dim, out);
    return;
  }
  // sum over i of C(n, i) t^i s^(n-i) p_i, as ((C0 s p0 + C1 t p1) s + C2 t^2 p2) s + ...
  const float s = 1.0f - t;
  float binomial = float(order - 1);
  for (int k = 0; k < dim; ++k) out[k] = s * p[k] + binomial * t * p[stride + k];
  float power = t * t;
  for (int i = 2; i < order; ++i, power *= t) {
    binomial *= float(order - i);
    binomial *= reciprocal(i);
    const float* q = p + i * stride;
    for (int k = 0; k < dim; ++k) out[k] = s * out[k] + binomial * power * q[k];
  }
}

void bezier_surface(const float* p, int dim, int uorder, int vorder, float u, float v, float* out) {
  const int row = vorder * dim;  // from control point (i, j) to (i + 1, j)
  std::vector<float> curve(std::size_t(std::max(uorder, vorder) * dim));
  if (vorder > uorder) {
    if (uorder < 2) return bezier_curve(p, dim, dim, vorder, v, out);
    // Each column j along u gives a control point of a curve in v.
    for (int j = 0; j < vorder; ++j)
      bezier_curve(p + j * dim, row, dim, uorder, u, &curve[j * dim]);
    return bezier_curve(curve.data(), dim, dim, vorder, v, out);
  }
  if (vorder < 2) return bezier_curve(p, row, dim, uorder, u, out);
  for (int i = 0; i < uorder; ++i) bezier_curve(p + i * row, dim, dim, vorder, v, &curve[i * dim]);
  bezier_curve(curve.data(), dim, dim, uorder, u, out);
}

namespace {

// One component's net of the de Casteljau construction: w(i, j), reduced in place.
class Net {
 public:
  Net(const float* p, int dim, int k, int uorder, int vorder)
      : rows_(uorder), cols_(vorder), stride_(vorder), w_(std::size_t(uorder * vorder)) {
    for (int i = 0; i < uorder; ++i)
      for (int j = 0; j < vorder; ++j) at(i, j) = p[(i * vorder + j) * dim + k];
  }
  // The stride stays vorder: the net shrinks in place, its points keep their places.
  float& at(int i, int j) { return w_[std::size_t(i * stride_ + j)]; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }

  // One step in both directions: each point interpolated in u, then in v.
  void bilinear_step(float u, float v) {
    const float us = 1.0f - u, vs = 1.0f - v;
    for (int i = 0; i + 1 < rows_; ++i) {
      at(i, 0) = us * at(i, 0) + u * at(i + 1, 0);
      for (int j = 0; j + 1 < cols_; ++j) {
        at(i, j + 1) = us * at(i, j + 1) + u * at(i + 1, j + 1);
        at(i, j) = vs * at(i, j) + v * at(i, j + 1);
      }
    }
    --rows_, --cols_;
  }

 private:
  int rows_, cols_, stride_;
  std::vector<float> w_;
};

// Interpolates a row of n values down to 2, in place.
void linear_steps(float* row, int n, float t) {
  const float s = 1.0f - t;
  for (; n > 2; --n)
    for (int j = 0; j + 1 < n; ++j) row[j] = s * row[j] + t * row[j + 1];
}

}  // namespace

void bezier_surface_tangents(const float* p, int dim, int uorder, int vorder, float u, float v,
                             float* out, float* du, float* dv) {
  const float us = 1.0f - u, vs = 1.0f - v;
  if (uorder < 2 || vorder < 2) {
    // A curve: no tangent across it, so no normal (the cross product is zero).
    bezier_surface(p, dim, uorder, vorder, u, v, out);
    for (int k = 0; k < dim; ++k) du[k] = dv[k] = 0.0f;
    return;
  }
  const int lower = std::min(uorder, vorder);
  for (int k = 0; k < dim; ++k) {
    Net n(p, dim, k, uorder, vorder);
    for (int h = 2; h < lower; ++h) n.bilinear_step(u, v);  // down to 2 in the lower order
    if (n.rows() == 2 && n.cols() == 2) {
      du[k] = vs * (n.at(1, 0) - n.at(0, 0)) + v * (n.at(1, 1) - n.at(0, 1));
      dv[k] = us * (n.at(0, 1) - n.at(0, 0)) + u * (n.at(1, 1) - n.at(1, 0));
      out[k] = us * (vs * n.at(0, 0) + v * n.at(0, 1)) + u * (vs * n.at(1, 0) + v * n.at(1, 1));
    } else if (n.rows() == 2) {
      // The last step in u: the point's row and the u-derivative's row, then down in v.
      std::vector<float> point(std::size_t(n.cols())), deriv(std::size_t(n.cols()));
      for (int j = 0; j < n.cols(); ++j) {
        deriv[j] = n.at(1, j) - n.at(0, j);
        point[j] = us * n.at(0, j) + u * n.at(1, j);
      }
      linear_steps(deriv.data(), n.cols(), v);
      linear_steps(point.data(), n.cols(), v);
      dv[k] = point[1] - point[0];
      du[k] = vs * deriv[0] + v * deriv[1];
      out[k] = vs * point[0] + v * point[1];
    } else {
      std::vector<float> point(std::size_t(n.rows())), deriv(std::size_t(n.rows()));
      for (int i = 0; i < n.rows(); ++i) {
        deriv[i] = n.at(i, 1) - n.at(i, 0);
        point[i] = vs * n.at(i, 0) + v * n.at(i, 1);
      }
      linear_steps(deriv.data(), n.rows(), u);
      linear_steps(point.data(), n.rows(), u);
      du[k] = point[1] - point[0];
      dv[k] = us * deriv[0] + u * deriv[1];
      out[k] = us * point[0] + u * point[1];
    }
  }
}

}  // namespace shadelab::gl
