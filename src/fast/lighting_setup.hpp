// The per-draw constants of the lighting equation in the form the SIMD lighting kernel reads:
// each enabled light and each material, with every per-light constant computed once, by the
// same float operations as src/lighting/lighting.cpp. Plain data; no lighting happens here.
#pragma once

#include <span>
#include <vector>

#include "shadelab/light.hpp"
#include "shadelab/material.hpp"

namespace shadelab::fast {

/// One enabled light. Positions and directions in eye space.
struct LightParams {
  bool positional = false;
  float pos[3] = {0, 0, 0};      ///< positional: position / w; directional: unit vector to it
  float kc = 1, kl = 0, kq = 0;  ///< attenuation (positional only)
  bool spot = false;             ///< positional light with a cone (cutoff != 180)
  bool spot_dark = false;        ///< a cone with a zero-length direction: no light at all
  float spot_dir[3] = {0, 0, -1};  ///< unit spot direction
  float cos_cutoff = -1, spot_exponent = 0;
  float const_spot = 1;          ///< directional lights: their spot factor (a constant)
  bool const_half = false;       ///< directional light and infinite viewer: h is a constant
  float half[3] = {0, 0, 1};     ///< that constant, normalized (0 when l + v = 0)
  float ambient[3], diffuse[3], specular[3];
  /// Light x material colours for per-pixel lighting, [front, back][ambient, diffuse,
  /// specular][rgb]: material * light, rounded once (the reference scales first).
  float product[2][3][3];
  bool ambient_product[2];  ///< [front, back]: product[side][0] is not black
};

/// One material's constants.
struct MaterialParams {
  float base[3];  ///< emission + material ambient * global ambient
  float ambient[3], diffuse[3], specular[3];
  float alpha = 1;  ///< clamped diffuse alpha
  float shininess = 0;
  bool phong_specular = false;  ///< the lecture's r . v form instead of Blinn's n . h
  int side = 0;                 ///< 0 front, 1 back: which of LightParams::product
};

struct LightingSetup {
  std::vector<LightParams> lights;
  MaterialParams front, back;
  bool local_viewer = false;
  bool separate_specular = false;
};

/// Whether the SIMD kernel computes `m` (Lambert or Oren-Nayar at roughness 0, which is
/// exactly Lambert; Blinn or Phong specular). Other materials use light_point per point.
bool simd_supports(const Material& m);

/// Fills `out` (reusing its storage) for the lights and both materials.
void make_lighting_setup(const LightModel& model, std::span<const Light> lights,
                         const Material& front, const Material& back, LightingSetup& out);

}  // namespace shadelab::fast
