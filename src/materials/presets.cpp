// The material presets. The lecture's come from its code; the classic table is the widely
// reproduced set of OpenGL materials (ambient, diffuse, specular, shininess), alpha 1.
#include "shadelab/materials.hpp"

#include <glm/vec3.hpp>

namespace shadelab {

namespace {

Material make(glm::vec3 a, glm::vec3 d, glm::vec3 s, float shininess) {
  Material m;
  m.ambient = glm::vec4(a, 1.0f);
  m.diffuse = glm::vec4(d, 1.0f);
  m.specular = glm::vec4(s, 1.0f);
  m.shininess = shininess;
  return m;
}

std::vector<MaterialPreset> build() {
  std::vector<MaterialPreset> p;
  // The lecture's materials.
  p.push_back({"shiny_red", "lecture: shiny red teapot (ambient = diffuse .41 .135 .067, specular 1, shininess 125)",
               make({.41f, .135f, .067f}, {.41f, .135f, .067f}, {1, 1, 1}, 125)});
  p.push_back({"lok_yau_hall", "lecture: the pale yellowish pink of Lok Yau Hall",
               make({.6f, .59f, .42f}, {.5f, .5f, .35f}, {.1f, .1f, .07f}, 1)});
  Material trans = make({.7f, 1, .85f}, {.7f, 1, .85f}, {1, 1, 1}, 100);
  trans.ambient.a = trans.diffuse.a = .3f;
  p.push_back({"transparent", "lecture: transMaterial1, alpha .3 (drawn blended)", trans});
  Material moon;
  moon.emission = {1, 1, .75f, 1};
  p.push_back({"moon", "lecture: the glowing moon, emission 1 1 .75", moon});
  p.push_back({"white_shiny", "lecture: the shiny white wall of the mesh-size experiments",
               make({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, 100)});
  // The classic OpenGL material table.
  p.push_back({"brass", "classic", make({.329412f, .223529f, .027451f}, {.780392f, .568627f, .113725f}, {.992157f, .941176f, .807843f}, 27.8974f)});
  p.push_back({"bronze", "classic", make({.2125f, .1275f, .054f}, {.714f, .4284f, .18144f}, {.393548f, .271906f, .166721f}, 25.6f)});
  p.push_back({"polished_bronze", "classic", make({.25f, .148f, .06475f}, {.4f, .2368f, .1036f}, {.774597f, .458561f, .200621f}, 76.8f)});
  p.push_back({"chrome", "classic", make({.25f, .25f, .25f}, {.4f, .4f, .4f}, {.774597f, .774597f, .774597f}, 76.8f)});
  p.push_back({"copper", "classic", make({.19125f, .0735f, .0225f}, {.7038f, .27048f, .0828f}, {.256777f, .137622f, .086014f}, 12.8f)});
  p.push_back({"polished_copper", "classic", make({.2295f, .08825f, .0275f}, {.5508f, .2118f, .066f}, {.580594f, .223257f, .0695701f}, 51.2f)});
  p.push_back({"gold", "classic", make({.24725f, .1995f, .0745f}, {.75164f, .60648f, .22648f}, {.628281f, .555802f, .366065f}, 51.2f)});
  p.push_back({"polished_gold", "classic", make({.24725f, .2245f, .0645f}, {.34615f, .3143f, .0903f}, {.797357f, .723991f, .208006f}, 83.2f)});
  p.push_back({"pewter", "classic", make({.105882f, .058824f, .113725f}, {.427451f, .470588f, .541176f}, {.333333f, .333333f, .521569f}, 9.84615f)});
  p.push_back({"silver", "classic", make({.19225f, .19225f, .19225f}, {.50754f, .50754f, .50754f}, {.508273f, .508273f, .508273f}, 51.2f)});
  p.push_back({"polished_silver", "classic", make({.23125f, .23125f, .23125f}, {.2775f, .2775f, .2775f}, {.773911f, .773911f, .773911f}, 89.6f)});
  p.push_back({"emerald", "classic", make({.0215f, .1745f, .0215f}, {.07568f, .61424f, .07568f}, {.633f, .727811f, .633f}, 76.8f)});
  p.push_back({"jade", "classic", make({.135f, .2225f, .1575f}, {.54f, .89f, .63f}, {.316228f, .316228f, .316228f}, 12.8f)});
  p.push_back({"obsidian", "classic", make({.05375f, .05f, .06625f}, {.18275f, .17f, .22525f}, {.332741f, .328634f, .346435f}, 38.4f)});
  p.push_back({"pearl", "classic", make({.25f, .20725f, .20725f}, {1, .829f, .829f}, {.296648f, .296648f, .296648f}, 11.264f)});
  p.push_back({"ruby", "classic", make({.1745f, .01175f, .01175f}, {.61424f, .04136f, .04136f}, {.727811f, .626959f, .626959f}, 76.8f)});
  p.push_back({"turquoise", "classic", make({.1f, .18725f, .1745f}, {.396f, .74151f, .69102f}, {.297254f, .30829f, .306678f}, 12.8f)});
  p.push_back({"black_plastic", "classic", make({0, 0, 0}, {.01f, .01f, .01f}, {.5f, .5f, .5f}, 32)});
  p.push_back({"cyan_plastic", "classic", make({0, .1f, .06f}, {0, .50980392f, .50980392f}, {.50196078f, .50196078f, .50196078f}, 32)});
  p.push_back({"green_plastic", "classic", make({0, 0, 0}, {.1f, .35f, .1f}, {.45f, .55f, .45f}, 32)});
  p.push_back({"red_plastic", "classic", make({0, 0, 0}, {.5f, 0, 0}, {.7f, .6f, .6f}, 32)});
  p.push_back({"white_plastic", "classic", make({0, 0, 0}, {.55f, .55f, .55f}, {.7f, .7f, .7f}, 32)});
  p.push_back({"yellow_plastic", "classic", make({0, 0, 0}, {.5f, .5f, 0}, {.6f, .6f, .5f}, 32)});
  p.push_back({"black_rubber", "classic", make({.02f, .02f, .02f}, {.01f, .01f, .01f}, {.4f, .4f, .4f}, 10)});
  p.push_back({"cyan_rubber", "classic", make({0, .05f, .05f}, {.4f, .5f, .5f}, {.04f, .7f, .7f}, 10)});
  p.push_back({"green_rubber", "classic", make({0, .05f, 0}, {.4f, .5f, .4f}, {.04f, .7f, .04f}, 10)});
  p.push_back({"red_rubber", "classic", make({.05f, 0, 0}, {.5f, .4f, .4f}, {.7f, .04f, .04f}, 10)});
  p.push_back({"white_rubber", "classic", make({.05f, .05f, .05f}, {.5f, .5f, .5f}, {.7f, .7f, .7f}, 10)});
  p.push_back({"yellow_rubber", "classic", make({.05f, .05f, 0}, {.5f, .5f, .4f}, {.7f, .7f, .04f}, 10)});
  return p;
}

}  // namespace

const std::vector<MaterialPreset>& material_presets() {
  static const std::vector<MaterialPreset> presets = build();  // immutable after first use
  return presets;
}

std::optional<Material> find_material_preset(const std::string& name) {
  for (const MaterialPreset& p : material_presets()) {
    if (p.name == name) return p.material;
  }
  return std::nullopt;
}

std::vector<std::string> material_preset_names() {
  std::vector<std::string> names;
  for (const MaterialPreset& p : material_presets()) names.push_back(p.name);
  return names;
}

}  // namespace shadelab
