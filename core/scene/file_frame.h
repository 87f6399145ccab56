#pragma once
// The one conversion between probeproxy's world frame (right-handed, Z up, metres:
// core/scene/world_frame.h) and every frame a file or an engine writes coordinates in: the
// scene file and proxies.json (their `up` and `meters_per_unit`), glTF, Unity, Unreal, Godot
// and Bevy. Each frame is a signed permutation of the world's axes and a unit, so every
// conversion is exact for the axes (a copy and a sign flip); only the unit rounds.
//
// Conventions (the scene file's, docs/cli_and_formats.md "Scene file"):
//   - points and half-extents scale with the unit, directions and rotations do not;
//   - a shape's own axes turn with the frame, so its half-extents are permuted and never
//     negated (Y-up half-extents (x, y, z) are world (x, z, y)), and an axis-aligned box keeps
//     the identity rotation;
//   - a rotation converts by conjugation, R' = A R A^T with A the axis change. For a quaternion
//     that is the vector part turned like a direction and multiplied by det(A) (a reflection
//     turns an axial vector the other way), w kept: exact, and a proper rotation even in the
//     left-handed engines.

#include "core/scene/world_frame.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace probeproxy {

// A frame: file axis i is sign[i] * world axis axis[i], in `metersPerUnit` metres per unit.
struct FileFrame {
  // A scene file's frame: Z up (the world's axes) or Y up ((x, y, z) in the file is the world
  // point (x, -z, y), glTF's axes), in `metersPerUnit` (> 0).
  FileFrame(UpAxis up, double metersPerUnit);
  FileFrame(std::array<int, 3> axis, std::array<double, 3> sign, double metersPerUnit);

  std::array<int, 3> axis;
  std::array<double, 3> sign;
  double determinant;  // +1 for a rotation of the axes, -1 for a reflection (left-handed)
  double metersPerUnit;
};

// Points (file units <-> metres).
glm::dvec3 filePointFromWorld(const FileFrame& frame, glm::dvec3 pointMeters);
glm::dvec3 worldPointFromFile(const FileFrame& frame, glm::dvec3 pointInFile);

// Unit directions (plane normals): axes only, never scaled.
glm::dvec3 fileDirectionFromWorld(const FileFrame& frame, glm::dvec3 direction);
glm::dvec3 worldDirectionFromFile(const FileFrame& frame, glm::dvec3 directionInFile);

// Half-extents or radii along a shape's own axes: permuted, never negated, scaled.
glm::dvec3 fileHalfExtentsFromWorld(const FileFrame& frame, glm::dvec3 halfExtentsMeters);
glm::dvec3 worldHalfExtentsFromFile(const FileFrame& frame, glm::dvec3 halfExtentsInFile);

// Lengths.
double fileLengthFromWorld(const FileFrame& frame, double lengthMeters);
double worldLengthFromFile(const FileFrame& frame, double lengthInFile);

// Rotations taking a shape's own frame to the file's / the world's frame.
glm::dquat fileRotationFromWorld(const FileFrame& frame, const glm::dquat& worldFromShape);
glm::dquat worldRotationFromFile(const FileFrame& frame, const glm::dquat& fileFromShape);

// A world-to-unit transform (a shape's point -> its unit box or unit sphere) written in the
// file's frame maps file points to the file shape's own unit space; this gives the world one:
// unitWorld = A^T * unitFile, xFile = (A xWorld) / metersPerUnit.
glm::dmat4 worldToUnitFromFile(const FileFrame& frame, const glm::dmat4& fileToUnit);

// The engines' frames (geometry/export/engine_probes.h says where each comes from).
// glTF, Godot and Bevy: right-handed, Y up, metres; world (x, y, z) -> (x, z, -y).
FileFrame gltfFrame();
// Unity: left-handed, Y up, metres; world (x, y, z) -> (-x, z, -y).
FileFrame unityFrame();
// Unreal: left-handed, Z up, centimetres; world (x, y, z) -> (x, -y, z) * 100.
FileFrame unrealFrame();

}  // namespace probeproxy
