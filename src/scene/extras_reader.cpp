// Textures on objects (glTexImage2D + glTexParameter + glTexEnv; files cached, sized before
// they are decoded) and the lecture's planar projected shadows (SPEC section 6).
#include <algorithm>

#include <glm/geometric.hpp>

#include "scene/scene_reader.hpp"
#include "shadelab/image.hpp"

namespace shadelab::detail {

using Type = JsonValue::Type;

namespace {

constexpr std::size_t kMaxShadows = 255;  // one stencil value each

// Image rows run top down; texture row 0 is t = 0, the bottom of the picture.
TextureLevel bottom_up(const Image& img) {
  TextureLevel level;
  level.width = img.width;
  level.height = img.height;
  for (int y = img.height - 1; y >= 0; --y) {
    level.rgba.insert(level.rgba.end(), img.pixel(0, y), img.pixel(0, y) + std::size_t(img.width) * 4);
  }
  return level;
}

}  // namespace

// "texture": "file.png" or {"file", "wrap", "filter", "env", "repeat"}. Mipmaps are built for
// the mipmapped filters (the default is trilinear).
void SceneReader::texture(const JsonValue& v, const std::string& path, SceneObject& o) {
  JsonValue as_object;  // "file.png" is {"file": "file.png"}
  if (v.type == Type::kString) {
    as_object.type = Type::kObject;
    as_object.line = v.line;
    as_object.column = v.column;
    as_object.members.push_back({"file", v.line, v.column, v});
  }
  const JsonValue& t = v.type == Type::kString ? as_object : v;
  if (!r_.object(t, path, {"file", "wrap", "filter", "env", "repeat"})) return;
  if (const JsonValue* rep = t.find("repeat")) {
    std::vector<double> n;
    if (r_.numbers(*rep, join_path(path, "repeat"), n, 2, -1, closed(-1e6, 1e6))) {
      o.texture_repeat = {float(n[0]), float(n[1])};
    }
  }
  Texture settings;
  if (int wrap = r_.choice(t, "wrap", path, {"repeat", "clamp", "clamp_to_edge"}); wrap >= 0) {
    settings.wrap_s = settings.wrap_t = TextureWrap(wrap);
  }
  int filter = r_.choice(t, "filter", path, {"nearest", "linear", "bilinear_mipmap", "trilinear"});
  const TextureFilter filters[] = {TextureFilter::kNearest, TextureFilter::kLinear,
                                   TextureFilter::kLinearMipmapNearest, TextureFilter::kLinearMipmapLinear};
  settings.min_filter = filter >= 0 ? filters[filter] : TextureFilter::kLinearMipmapLinear;
  settings.mag_filter = filter == 0 ? TextureFilter::kNearest : TextureFilter::kLinear;
  if (int env = r_.choice(t, "env", path, {"modulate", "replace", "decal", "blend"}); env >= 0) {
    o.texture_env = TextureEnvMode(env);
  }
  const JsonValue* file = t.find("file");
  if (!file) {
    r_.error(t, path, "missing required key \"file\"");
    return;
  }
  o.texture = load_texture(*file, v.type == Type::kString ? path : join_path(path, "file"), settings);
}

// Loads (once per file and settings) a PNG or JPEG, checking its size before decoding it.
std::shared_ptr<const Texture> SceneReader::load_texture(const JsonValue& file, const std::string& path,
                                                         const Texture& settings) {
  if (!r_.is_type(file, Type::kString, path)) return nullptr;
  std::string full = resolve(file.text);
  if (!confined(file, path, full)) return nullptr;
  std::string key = full + "|" + std::to_string(int(settings.wrap_s)) + "|" +
                    std::to_string(int(settings.min_filter)) + "|" + std::to_string(int(settings.mag_filter));
  if (auto it = textures_.find(key); it != textures_.end()) return it->second;
  int w = 0, h = 0;
  const int limit = options_.max_texture_side;
  // A header that cannot be read is reported by read_image below.
  if (read_image_size(full, w, h, nullptr) && (w > limit || h > limit)) {
    r_.error(file, path, "the texture is " + std::to_string(w) + " x " + std::to_string(h) +
                             ", more than the limit of " + std::to_string(limit) + " x " +
                             std::to_string(limit) + " (--max-texture-size)");
    return nullptr;
  }
  Image img;
  std::string error;
  if (!read_image(full, img, &error, limit)) {
    r_.error(file, path, error);
    return nullptr;
  }
  auto tex = std::make_shared<Texture>(settings);
  tex->levels.push_back(bottom_up(img));
  generate_mipmaps(*tex);
  return textures_[key] = std::move(tex);
}

void SceneReader::shadows(const JsonValue& v, Scene& s) {
  if (!r_.is_type(v, Type::kArray, "shadows")) return;
  if (v.items.size() > kMaxShadows) {
    r_.error(v, "shadows", std::to_string(v.items.size()) + " shadows, more than the limit of " +
                               std::to_string(kMaxShadows));
    return;
  }
  for (std::size_t i = 0; i < v.items.size(); ++i) shadow(v.items[i], index_path("shadows", i), s);
}

// {"plane": [a, b, c, d], "light": i, "color": [r, g, b, a], "receiver": "object name"}
void SceneReader::shadow(const JsonValue& v, const std::string& path, Scene& s) {
  if (!r_.object(v, path, {"plane", "light", "color", "receiver"})) return;
  PlanarShadow sh;
  if (r_.vec4(v, "plane", path, sh.plane) && glm::length(glm::vec3(sh.plane)) == 0.0f) {
    r_.error(*v.find("plane"), join_path(path, "plane"), "(a, b, c) must not be the zero vector");
  }
  if (s.lights.empty()) {
    r_.error(v, path, "a shadow needs a light, and the scene has none");
  } else {
    r_.integer(v, "light", path, sh.light, 0, int(s.lights.size()) - 1);
  }
  r_.color(v, "color", path, sh.color, closed(0, 1));
  const JsonValue* receiver = v.find("receiver");
  if (!receiver) {
    r_.error(v, path, "missing required key \"receiver\"");
  } else if (r_.string(v, "receiver", path, sh.receiver)) {
    std::vector<std::string> names;
    for (const SceneObject& o : s.objects) names.push_back(o.name);
    if (std::find(names.begin(), names.end(), sh.receiver) == names.end()) {
      r_.error(*receiver, join_path(path, "receiver"),
               "no object named \"" + sh.receiver + "\"" + suggestion(sh.receiver, names));
    }
  }
  s.shadows.push_back(sh);
}

}  // namespace shadelab::detail
