// The evaluator state of a context (GL 1.1 section 5.1, table 6.20): the one- and
// two-dimensional maps of each target, their enables, GL_AUTO_NORMAL and the grids of
// glMapGrid. Plain data; gl/src/eval.cpp defines the commands that change and use it.
#pragma once

#include <GL/gl.h>

#include <array>
#include <vector>

namespace shadelab::gl {

/// GL_MAX_EVAL_ORDER (Mesa's).
inline constexpr int kMaxEvalOrder = 30;
/// The nine targets of each dimension, GL_MAPn_COLOR_4 .. GL_MAPn_VERTEX_4, are consecutive
/// enums; a map's slot is its target minus the first.
inline constexpr int kEvalTargets = 9;

/// A glMap1 map: `order` control points of the target's component count, tightly packed.
struct EvalMap1 {
  int order = 1;
  float u1 = 0.0f, u2 = 1.0f;
  float du = 1.0f;  // 1 / (u2 - u1), as Mesa keeps it: the parameter is (u - u1) * du
  std::vector<float> points;
};

/// A glMap2 map: control point (i, j) at (i * vorder + j) * components.
struct EvalMap2 {
  int uorder = 1, vorder = 1;
  float u1 = 0.0f, u2 = 1.0f, v1 = 0.0f, v2 = 1.0f;
  float du = 1.0f, dv = 1.0f;
  std::vector<float> points;
};

/// What glPushAttrib(GL_EVAL_BIT) saves: the enables and the grids (the maps themselves
/// belong to no attribute group).
struct EvalAttribs {
  std::array<bool, kEvalTargets> map1_enabled{}, map2_enabled{};
  bool auto_normal = false;
  int grid1_un = 1;
  float grid1_u1 = 0.0f, grid1_u2 = 1.0f, grid1_du = 1.0f;
  int grid2_un = 1, grid2_vn = 1;
  float grid2_u1 = 0.0f, grid2_u2 = 1.0f, grid2_du = 1.0f;
  float grid2_v1 = 0.0f, grid2_v2 = 1.0f, grid2_dv = 1.0f;
};

struct EvalState {
  EvalAttribs attribs;
  std::array<EvalMap1, kEvalTargets> map1;
  std::array<EvalMap2, kEvalTargets> map2;
  EvalState();
};

}  // namespace shadelab::gl
