// `shadelab materials`: lists the material presets; `--sheet OUT.png` renders a labelled
// sphere per preset under a white directional light from (1, 1, 1).
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "shadelab/contact_sheet.hpp"
#include "shadelab/materials.hpp"
#include "shadelab/render.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab::cli {

namespace {

struct MaterialsArgs {
  std::string sheet;
  int size = 160;
};

void print_presets() {
  std::printf("%-16s %-22s %-22s %-22s %9s\n", "name", "ambient", "diffuse", "specular", "shininess");
  auto rgb = [](const glm::vec4& c) {
    char b[64];
    std::snprintf(b, sizeof b, "%.3g %.3g %.3g", c.r, c.g, c.b);
    return std::string(b);
  };
  for (const MaterialPreset& p : material_presets()) {
    std::printf("%-16s %-22s %-22s %-22s %9.4g\n", p.name.c_str(), rgb(p.material.ambient).c_str(),
                rgb(p.material.diffuse).c_str(), rgb(p.material.specular).c_str(), p.material.shininess);
  }
}

Scene sphere_scene(const Material& m, int size) {
  Scene s;
  s.width = s.height = size;
  s.samples = 4;
  s.background = {0.08f, 0.08f, 0.1f, 1.0f};
  s.camera.eye = {0, 0, 6};
  s.camera.fovy_degrees = 22;
  SceneLight l;
  l.light = default_light(0);
  l.light.position = {1, 1, 1, 0};
  s.lights.push_back(l);
  SceneObject o;
  o.mesh = std::make_shared<Mesh>(make_sphere({1.0f, 64, 32}));
  o.front = m;
  o.shading = ShadingMode::kPhong;
  // As a scene file's "blend": "auto": a translucent material is blended over the background.
  if (m.diffuse.a < 1.0f) o.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  s.objects.push_back(o);
  return s;
}

int run(const MaterialsArgs& a) {
  if (a.sheet.empty()) {
    print_presets();
    return kExitOk;
  }
  std::unique_ptr<Font> font = load_default_font("materials");
  if (!font) return kExitFailure;
  std::string error;
  std::vector<SheetCell> cells;
  for (const MaterialPreset& p : material_presets()) {
    cells.push_back({render_scene(sphere_scene(p.material, a.size)), p.name});
  }
  Image sheet = make_contact_sheet(cells, 6, *font, "shadelab material presets");
  if (!write_png(sheet, a.sheet, &error)) {
    std::cerr << "shadelab materials: " << error << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Action add_materials_command(CLI::App& app) {
  auto a = std::make_shared<MaterialsArgs>();
  CLI::App* cmd = app.add_subcommand("materials", "List the material presets, or render them as a sheet");
  cmd->add_option("--sheet", a->sheet, "Render a labelled sphere per preset into this PNG");
  cmd->add_option("--size", a->size, "Size of each sphere picture in pixels")->check(CLI::Range(16, 1024));
  cmd->footer("Examples:\n  shadelab materials\n  shadelab materials --sheet materials.png\n"
              "Use a preset in a scene by name: \"material\": \"brass\".");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
