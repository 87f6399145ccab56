#pragma once
// The level the add-on hands over: a list of parts, each either one of the scene file's own
// level meshes (loaded exactly as the CLI loads it, so the figures match the CLI's) or
// triangles taken from Blender mesh data. Parts are appended in list order.
//
//   {"scene_level": i}                        the scene's i-th `level` mesh file
//   {"name": s, "vertices": buf, "triangles": buf}
//       vertices: flat x, y, z in world metres, Z up (float32 or float64 buffer or sequence);
//       triangles: flat vertex indices, three per triangle (any integer buffer or sequence)

#include "core/scene/scene.h"
#include "plugin/jobs/scene_input.h"

#include <pybind11/pybind11.h>

#include <vector>

namespace probeproxy::python {

// Reads the parts out of Python (needs the GIL). Throws InputError (naming the scene file)
// for a malformed part: an index out of range, a vertex count that is not a multiple of 3, a
// triangle index past the vertices or a non-finite coordinate.
// The jobs load them (plugin/jobs/scene_input.h) with the GIL released.
std::vector<jobs::LevelSource> levelSources(const Scene& scene, const pybind11::list& parts);

}  // namespace probeproxy::python
