#include "geometry/export/export_frame.h"

namespace probeproxy {

namespace {

// Y up -> Z up: (x, y, z) -> (x, -z, y); and back: (x, y, z) -> (x, z, -y). Exact.
glm::dvec3 toWorldAxes(const ExportFrame& frame, glm::dvec3 v) {
  return frame.up == UpAxis::Y ? zUpFromYUp(v) : v;
}

glm::dvec3 toFileAxes(const ExportFrame& frame, glm::dvec3 v) {
  return frame.up == UpAxis::Y ? yUpFromZUp(v) : v;
}

// A shape's own axes turn with the file's, so its extents are permuted, never negated.
glm::dvec3 swappedYZ(const ExportFrame& frame, glm::dvec3 v) {
  return frame.up == UpAxis::Y ? glm::dvec3(v.x, v.z, v.y) : v;
}

glm::dquat withVectorPart(const glm::dquat& q, glm::dvec3 v) {
  glm::dquat out;  // members, not the constructor: its argument order depends on GLM's config
  out.w = q.w;
  out.x = v.x;
  out.y = v.y;
  out.z = v.z;
  return out;
}

}  // namespace

glm::dvec3 filePointFromWorld(const ExportFrame& frame, glm::dvec3 p) {
  return toFileAxes(frame, p) / frame.metersPerUnit;
}

glm::dvec3 worldPointFromFile(const ExportFrame& frame, glm::dvec3 p) {
  return toWorldAxes(frame, p * frame.metersPerUnit);
}

glm::dvec3 fileDirectionFromWorld(const ExportFrame& frame, glm::dvec3 d) {
  return toFileAxes(frame, d);
}

glm::dvec3 worldDirectionFromFile(const ExportFrame& frame, glm::dvec3 d) {
  return toWorldAxes(frame, d);
}

glm::dvec3 fileHalfExtentsFromWorld(const ExportFrame& frame, glm::dvec3 h) {
  return swappedYZ(frame, h) / frame.metersPerUnit;
}

glm::dvec3 worldHalfExtentsFromFile(const ExportFrame& frame, glm::dvec3 h) {
  return swappedYZ(frame, h * frame.metersPerUnit);
}

double fileLengthFromWorld(const ExportFrame& frame, double meters) {
  return meters / frame.metersPerUnit;
}

double worldLengthFromFile(const ExportFrame& frame, double length) {
  return length * frame.metersPerUnit;
}

glm::dquat fileRotationFromWorld(const ExportFrame& frame, const glm::dquat& q) {
  return withVectorPart(q, toFileAxes(frame, glm::dvec3(q.x, q.y, q.z)));
}

glm::dquat worldRotationFromFile(const ExportFrame& frame, const glm::dquat& q) {
  return withVectorPart(q, toWorldAxes(frame, glm::dvec3(q.x, q.y, q.z)));
}

glm::dmat4 worldToUnitFromFile(const ExportFrame& frame, const glm::dmat4& fileToUnit) {
  // Columns of the world-from-file axis change; GLM matrices are column-major.
  glm::dmat4 axes(0.0);
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 e(0.0);
    e[c] = 1.0;
    const glm::dvec3 column = toWorldAxes(frame, e);
    for (int r = 0; r < 3; ++r) axes[c][r] = column[r];
  }
  axes[3][3] = 1.0;
  // xFile = axes^T xWorld / metersPerUnit: a linear map, translation 0.
  glm::dmat4 fileFromWorld = glm::transpose(axes);
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) fileFromWorld[c][r] /= frame.metersPerUnit;
  }
  return axes * fileToUnit * fileFromWorld;
}

}  // namespace probeproxy
