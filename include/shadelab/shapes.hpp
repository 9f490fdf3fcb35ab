// Built-in shapes (the lecture's objects and the usual GLUT solids) and Wavefront OBJ loading.
// Every function returns an object-space mesh with normals and texture coordinates,
// counter-clockwise front faces; no transforms, no materials.
#pragma once

#include <string>
#include <vector>

#include "shadelab/diagnostics.hpp"
#include "shadelab/mesh.hpp"

namespace shadelab {

/// The Utah teapot from Newell's 32 bicubic Bezier patches, sized like glutSolidTeapot(size):
/// the body's rim radius is about `size`, spout toward +x, lid toward +y, sitting about its
/// centre. `tessellation` is the number of segments along each patch parameter (>= 1).
/// Texture coordinates are the patch parameters (u, v).
struct TeapotParams {
  float size = 1.0f;
  int tessellation = 10;
};
Mesh make_teapot(const TeapotParams& p);

/// UV sphere centred at the origin, poles on the y axis. slices >= 3 around, stacks >= 2.
struct SphereParams {
  float radius = 1.0f;
  int slices = 32;
  int stacks = 16;
};
Mesh make_sphere(const SphereParams& p);

/// Cylinder around the y axis from y = 0 to y = height (the lecture's cylinder: radius 1,
/// height 2). `caps` closes both ends with flat disks. `angle_colors` gives each side vertex
/// the lecture's colour (cos t, 0, sin t, 1), t the angle around the axis.
struct CylinderParams {
  float radius = 1.0f;
  float height = 2.0f;
  int slices = 32;  ///< >= 3
  int stacks = 1;   ///< >= 1
  bool caps = true;
  bool angle_colors = false;
};
Mesh make_cylinder(const CylinderParams& p);

/// Cone around the y axis, base disk at y = 0 (capped unless `cap` is false), apex at y = height.
struct ConeParams {
  float radius = 1.0f;
  float height = 2.0f;
  int slices = 32;  ///< >= 3
  int stacks = 1;   ///< >= 1
  bool cap = true;
};
Mesh make_cone(const ConeParams& p);

/// Torus in the xy plane around the z axis (as glutSolidTorus).
struct TorusParams {
  float major_radius = 1.0f;   ///< centre of the tube to the centre of the torus
  float minor_radius = 0.25f;  ///< radius of the tube
  int sides = 16;              ///< around the tube, >= 3
  int rings = 32;              ///< around the axis, >= 3
};
Mesh make_torus(const TorusParams& p);

/// Axis-aligned cube centred at the origin, edge `size`, one normal per face.
Mesh make_cube(float size);

/// The lecture's tetrahedron: vertices (-1,-1,-1), (1,-1,1), (-1,1,1), (1,1,-1), one
/// normal per face exactly as the lecture's glNormal3f calls give them (normalized).
Mesh make_tetrahedron();

/// A grid of nx by ny quads (the mesh-size experiment's wall) in the plane z = 0, centred at the
/// origin, width along x, height along y, facing +z. Texture coordinates span [0, 1].
struct WallParams {
  float width = 2.0f;
  float height = 2.0f;
  int nx = 1;  ///< >= 1
  int ny = 1;  ///< >= 1
};
Mesh make_wall(const WallParams& p);

/// A square floor of side `size` in the plane y = 0, facing +y, split into n x n quads.
Mesh make_plane(float size, int n);

/// A disk (or annulus when inner > 0) in the plane z = 0, facing +z.
struct DiskParams {
  float inner_radius = 0.0f;
  float outer_radius = 1.0f;
  int slices = 32;  ///< >= 3
  int loops = 1;    ///< >= 1
};
Mesh make_disk(const DiskParams& p);

/// Loads a Wavefront OBJ file (all its shapes merged into one mesh, polygons triangulated).
/// Normals come from the file where every face has them, otherwise they are computed smooth.
/// Problems are appended to `diags` (with the file name); returns false on failure.
bool load_obj(const std::string& path, Mesh& out, Diagnostics& diags);

}  // namespace shadelab
