// The name -> entry point table of libshadelab-gl (generated from the OpenGL registry by
// gl/api/generate.py into gl/generated/proc_table.cpp): what OSMesaGetProcAddress, and the
// GLX, EGL and GLVND layers, hand out. Private to the library; a lookup, nothing else.
#pragma once

namespace shadelab::gl {

/// A function pointer of no particular type, as GetProcAddress functions return them.
using Proc = void (*)();

/// The exported gl* or OSMesa* function called `name` (case-sensitive), or nullptr when the
/// library has none by that name (a command still pending is none). Binary search over a
/// sorted table; safe from any thread.
Proc find_proc(const char* name) noexcept;

}  // namespace shadelab::gl
