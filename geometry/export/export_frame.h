#pragma once
// The frame proxies.json is written in: the scene file's own up axis and unit, so that the
// engine side reads what the artist declared. probeproxy's world is right-handed, Z up, metres
// (core/scene/world_frame.h); a Y-up file point (x, y, z) is the world point (x, -z, y).
//
// Conventions are the scene file's (geometry/scene/scene_file.cpp): a box's own frame turns
// with the file's, so Y-up half-extents (x, y, z) are world (x, z, y) and an axis-aligned box
// keeps the identity rotation. Every conversion here is exact for the axes (a signed
// permutation); only the unit scale rounds, and it rounds the same way the scene reader does.

#include "core/scene/world_frame.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace probeproxy {

struct ExportFrame {
  UpAxis up = UpAxis::Z;
  double metersPerUnit = 1.0;  // > 0
};

// Points (file units <-> metres).
glm::dvec3 filePointFromWorld(const ExportFrame& frame, glm::dvec3 pointMeters);
glm::dvec3 worldPointFromFile(const ExportFrame& frame, glm::dvec3 pointInFile);

// Unit directions (plane normals): axes only.
glm::dvec3 fileDirectionFromWorld(const ExportFrame& frame, glm::dvec3 direction);
glm::dvec3 worldDirectionFromFile(const ExportFrame& frame, glm::dvec3 directionInFile);

// Half-extents or radii along a shape's own axes.
glm::dvec3 fileHalfExtentsFromWorld(const ExportFrame& frame, glm::dvec3 halfExtentsMeters);
glm::dvec3 worldHalfExtentsFromFile(const ExportFrame& frame, glm::dvec3 halfExtentsInFile);

// Lengths, and quantities per length (cheap_k's k: per metre <-> per file unit).
double fileLengthFromWorld(const ExportFrame& frame, double lengthMeters);
double worldLengthFromFile(const ExportFrame& frame, double lengthInFile);

// Rotations taking a shape's own frame to the file's / the world's frame: conjugation by the
// axis change, exact (the vector part is permuted like a direction, w is kept).
glm::dquat fileRotationFromWorld(const ExportFrame& frame, const glm::dquat& worldFromShape);
glm::dquat worldRotationFromFile(const ExportFrame& frame, const glm::dquat& fileFromShape);

// A world-to-unit transform (a shape's point -> its unit box or unit sphere) written in the
// file's frame maps file points to the file shape's own unit space; this gives the world one:
// unitWorld = axes * unitFile, xFile = (axes^T xWorld) / metersPerUnit.
glm::dmat4 worldToUnitFromFile(const ExportFrame& frame, const glm::dmat4& fileToUnit);

}  // namespace probeproxy
