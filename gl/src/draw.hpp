// The vertex path shared by glBegin/glEnd (draw.cpp) and the vertex arrays (array_mesh.cpp):
// per-vertex transformation and lighting with the core's light_point, then primitives handed
// to the core's draw_triangles. It never rasterizes or shades pixels itself.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Vertices gathered before a long primitive is drawn part way (bounds memory).
inline constexpr std::size_t kFlushVertices = 1u << 16;

/// Starts a primitive of a valid glBegin `mode`: fixes the transforms and the enabled lights.
void begin_primitive(GlContext& c, GLenum mode);

/// Transforms `object_position` by the modelview, lights it with the current normal, colour
/// and material (or takes the current colour when lighting is off), and adds it.
void emit_vertex(GlContext& c, const glm::vec4& object_position);

/// Draws what is left of the primitive and ends it (the caller's buffer is updated at the
/// next flush).
void end_primitive(GlContext& c);

/// Fills object-space attributes of array elements first .. first + n - 1: positions,
/// normals and, when their pointers are not null, colours (unused under lighting) and
/// texture coordinates, taking the current value where an array is disabled.
/// Called through a reference to the caller's function object: nothing is copied or
/// allocated per draw.
class ElementLoader {
 public:
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, ElementLoader>)
  ElementLoader(F&& f)  // NOLINT: converts from any loader function object
      : object_(const_cast<void*>(static_cast<const void*>(&f))),
        call_([](void* o, std::size_t first, std::size_t n, glm::vec4* p, glm::vec3* nm, glm::vec4* c,
                 glm::vec4* t) { (*static_cast<std::remove_reference_t<F>*>(o))(first, n, p, nm, c, t); }) {}
  void operator()(std::size_t first, std::size_t n, glm::vec4* positions, glm::vec3* normals,
                  glm::vec4* colors, glm::vec4* texcoords) const {
    call_(object_, first, n, positions, normals, colors, texcoords);
  }

 private:
  void* object_;
  void (*call_)(void*, std::size_t, std::size_t, glm::vec4*, glm::vec3*, glm::vec4*, glm::vec4*);
};

/// Where an ExtraLoader writes GL 1.4's per-vertex attributes of a range of elements: each
/// output is null when the draw does not read that attribute.
struct ExtraOutputs {
  glm::vec3* secondary = nullptr;  ///< secondary colours, red, green and blue as given
  float* fog = nullptr;            ///< fog coordinates as given
  /// Texture units 1 and up (GL 1.3): their texture coordinates as given (entry 0 unused: the
  /// ElementLoader gives unit 0's).
  std::array<glm::vec4*, kMaxTextureUnits> texcoords{};
};
/// Loads GL 1.3-1.4's attributes of array elements first .. first + n - 1 (from their arrays,
/// or the current values where an array is disabled).
using ExtraLoader = std::function<void(std::size_t first, std::size_t n, const ExtraOutputs& out)>;

/// glDrawArrays / glDrawElements in one go when the material is the same at every vertex:
/// the draw's `count` element indices are `direct` (32-bit indices of GL_TRIANGLES, read in
/// place) or else c.array_scratch.sequence (UINT32_MAX for one that does not fit), lo and hi
/// the smallest and largest; each element in that range is loaded and transformed once and
/// lit by the pipeline, not once per index. False, with nothing drawn, when the draw must go
/// vertex by vertex instead (flat quads or polygons, colour material with a colour array,
/// sparse indices, w != 1). `from_elements`: a glDrawElements draw, whose quads llvmpipe splits
/// from their second vertex. `extra`: GL 1.4's attributes (null: the current values).
bool draw_array_mesh(GlContext& c, GLenum mode, bool per_vertex_color, bool from_elements, std::size_t count,
                     const std::uint32_t* direct, std::uint32_t lo, std::uint32_t hi,
                     const ElementLoader& load, const ExtraLoader* extra = nullptr);

}  // namespace shadelab::gl
