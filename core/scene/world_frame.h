#pragma once
// probeproxy works in one world frame: right-handed, Z up, metres (Blender's). Scene files
// and meshes may be Y-up (glTF, most engines) or in other units; they are converted once, on
// load, and converted back on write. A Y-up point (x, y, z) is the Z-up point (x, -z, y): a
// +90 degree rotation about X. Rotations, extents and units convert in core/scene/file_frame.h,
// the one conversion between the world and every file or engine frame.

#include <glm/vec3.hpp>

namespace probeproxy {

enum class UpAxis { Y, Z };

// Points and directions.
inline glm::dvec3 zUpFromYUp(glm::dvec3 p) { return {p.x, -p.z, p.y}; }
inline glm::dvec3 yUpFromZUp(glm::dvec3 p) { return {p.x, p.z, -p.y}; }
inline glm::vec3 zUpFromYUp(glm::vec3 p) { return {p.x, -p.z, p.y}; }
inline glm::vec3 yUpFromZUp(glm::vec3 p) { return {p.x, p.z, -p.y}; }

}  // namespace probeproxy
