// Wavefront OBJ files: any bytes through the OBJ loader (indices, counts, normals).
#include <cstdint>

#include "fuzz_util.hpp"
#include "shadelab/diagnostics.hpp"
#include "shadelab/shapes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 16)) return 0;  // bounded work per input
  std::string path = shadelab::fuzz::write_input("input.obj", data, size);
  shadelab::Mesh mesh;
  shadelab::Diagnostics diags;
  if (!shadelab::load_obj(path, mesh, diags)) return 0;
  for (const shadelab::Triangle& t : mesh.triangles) {
    for (std::uint32_t i : t) {
      if (i >= mesh.positions.size()) __builtin_trap();  // the loader must have checked
    }
  }
  return 0;
}
