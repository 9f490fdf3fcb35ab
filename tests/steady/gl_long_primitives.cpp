// A primitive of more vertices than libshadelab-gl keeps between glBegin and glEnd is drawn in
// parts as its vertices arrive (draw.cpp's flush_part), each part keeping the vertices the
// next one still needs: the first of a fan, the last two of a strip, the rest of an unfinished
// quad. It must come out byte for byte as the same triangles given in short primitives:
// every mode that flushes, flat and smooth, unlit (colours per vertex), lit by the pipeline
// (lighting deferred) and lit per glVertex call after a glMaterial inside the primitive.
// Depth testing is off, so triangles drawn out of order, or from the wrong kept vertex,
// show.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

constexpr int kW = 256, kH = 192;     // 4 x 3 tiles of 64 pixels
constexpr int kVertices = 150000;     // more than two parts of 65,536
constexpr int kShortVertices = 9000;  // per short primitive (a multiple of 3, 4 and 2)

struct Vertex {
  float position[3], normal[3];
  std::uint8_t color[4];
};

// Small triangles along a slow curve over the viewport, overlapping one another.
std::vector<Vertex> make_vertices() {
  std::vector<Vertex> v(kVertices);
  std::uint32_t seed = 12345u;
  auto random = [&seed] {  // in [-1, 1)
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 23) - 1.0f;
  };
  for (int i = 0; i < kVertices; ++i) {
    const float t = float(i);
    v[i].position[0] = 0.85f * std::sin(t * 0.00043f) + 0.05f * random();
    v[i].position[1] = 0.85f * std::sin(t * 0.00071f + 1.0f) + 0.05f * random();
    v[i].position[2] = 0.5f * random();
    v[i].normal[0] = random(), v[i].normal[1] = random(), v[i].normal[2] = 1.0f;
    for (int c = 0; c < 3; ++c) v[i].color[c] = std::uint8_t(128.0f + 127.0f * random());
    v[i].color[3] = 255;
  }
  return v;
}

enum class Light { kOff, kDeferred, kChanged };

constexpr int kMaterialChange = 1001;  // the vertex before which kChanged changes the material

void set_material(bool changed) {
  const GLfloat first[] = {0.8f, 0.3f, 0.2f, 1.0f}, second[] = {0.2f, 0.5f, 0.9f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, changed ? second : first);
}

void vertex(const Vertex& v) {
  glColor4ubv(v.color);
  glNormal3fv(v.normal);
  glVertex3fv(v.position);
}

// Sets up the lighting of a case, with the material before any change.
void set_lighting(Light light, GLenum shade) {
  glShadeModel(shade);
  if (light == Light::kOff) {
    glDisable(GL_LIGHTING);
    return;
  }
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  const GLfloat position[] = {0.3f, 0.5f, 1.0f, 0.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
  set_material(false);
}

// The whole sequence as one primitive.
void draw_long(const std::vector<Vertex>& v, GLenum mode, Light light) {
  glBegin(mode);
  for (int i = 0; i < kVertices; ++i) {
    if (light == Light::kChanged && i == kMaterialChange) set_material(true);
    vertex(v[i]);
  }
  glEnd();
}

// The same triangles in short primitives: a fan's first vertex again in each, a strip's last
// two vertices again at the start of the next (which starts on an even vertex, as the long
// strip's triangle there: the same winding). With kChanged every short primitive is lit per
// glVertex call from its start (a glMaterial call inside a primitive ends the deferral), each
// vertex with the material the long primitive lit it with, so that both light alike.
void draw_short(const std::vector<Vertex>& v, GLenum mode, Light light) {
  const bool fan = mode == GL_TRIANGLE_FAN;
  const int overlap = (mode == GL_TRIANGLE_STRIP || mode == GL_QUAD_STRIP) ? 2 : fan ? 1 : 0;
  for (int start = fan ? 1 : 0; start < kVertices;) {
    const int end = std::min(kVertices, start + kShortVertices);
    glBegin(mode);
    if (light == Light::kChanged) set_material(false);
    if (fan) vertex(v[0]);
    for (int i = start; i < end; ++i) {
      if (light == Light::kChanged && (i == start || i == kMaterialChange)) set_material(i >= kMaterialChange);
      vertex(v[i]);
    }
    glEnd();
    if (end == kVertices) break;
    start = end - overlap;
  }
}

std::vector<unsigned char> render(std::vector<unsigned char>& buffer, const std::vector<Vertex>& v, GLenum mode,
                                  GLenum shade, Light light, bool long_primitive) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  set_lighting(light, shade);
  if (long_primitive) draw_long(v, mode, light);
  else draw_short(v, mode, light);
  glFinish();
  return buffer;
}

const char* mode_name(GLenum mode) {
  switch (mode) {
    case GL_TRIANGLES: return "GL_TRIANGLES";
    case GL_TRIANGLE_STRIP: return "GL_TRIANGLE_STRIP";
    case GL_TRIANGLE_FAN: return "GL_TRIANGLE_FAN";
    case GL_QUADS: return "GL_QUADS";
    case GL_QUAD_STRIP: return "GL_QUAD_STRIP";
    default: return "GL_POLYGON";
  }
}

}  // namespace

int main() {
  std::vector<unsigned char> buffer(std::size_t(kW) * kH * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  glViewport(0, 0, kW, kH);
  glDisable(GL_DEPTH_TEST);
  const std::vector<Vertex> v = make_vertices();
  int failures = 0, cases = 0;
  const char* light_names[] = {"unlit", "lit (deferred)", "lit, material changed inside"};
  for (GLenum mode : {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP}) {
    for (GLenum shade : {GL_SMOOTH, GL_FLAT}) {
      for (Light light : {Light::kOff, Light::kDeferred, Light::kChanged}) {
        const std::vector<unsigned char> whole = render(buffer, v, mode, shade, light, true);
        const std::vector<unsigned char> parts = render(buffer, v, mode, shade, light, false);
        ++cases;
        std::size_t lit = 0;
        for (std::size_t p = 0; p < whole.size(); p += 4) lit += (whole[p] | whole[p + 1] | whole[p + 2]) != 0;
        const char* what = light_names[int(light)];
        if (lit < std::size_t(kW) * kH / 4) {
          std::printf("FAIL %s, %s, %s: only %zu pixels drawn\n", mode_name(mode),
                      shade == GL_FLAT ? "flat" : "smooth", what, lit);
          ++failures;
          continue;
        }
        for (std::size_t p = 0; p < whole.size(); p += 4) {
          if (std::memcmp(&whole[p], &parts[p], 4) != 0) {
            const int x = int(p / 4) % kW, y = int(p / 4) / kW;
            std::printf("FAIL %s, %s, %s: pixel (%d, %d) is %d %d %d in one primitive, %d %d %d in short ones\n",
                        mode_name(mode), shade == GL_FLAT ? "flat" : "smooth", what, x, y, whole[p], whole[p + 1],
                        whole[p + 2], parts[p], parts[p + 1], parts[p + 2]);
            ++failures;
            break;
          }
        }
      }
    }
  }
  OSMesaDestroyContext(ctx);
  if (failures) return 1;
  std::printf("ok: %d cases of %d vertices in one primitive, as in short ones\n", cases, kVertices);
  return 0;
}
