#include "core/scene/file_frame.h"

#include <stdexcept>

namespace probeproxy {

namespace {

glm::dquat withVectorPart(const glm::dquat& q, glm::dvec3 v) {
  glm::dquat out;  // members, not the constructor: its argument order depends on GLM's config
  out.w = q.w;
  out.x = v.x;
  out.y = v.y;
  out.z = v.z;
  return out;
}

glm::dvec3 permuted(const FileFrame& frame, glm::dvec3 w) {
  return {w[frame.axis[0]], w[frame.axis[1]], w[frame.axis[2]]};
}

glm::dvec3 unpermuted(const FileFrame& frame, glm::dvec3 f) {
  glm::dvec3 w(0.0);
  for (int i = 0; i < 3; ++i) w[frame.axis[i]] = f[i];
  return w;
}

// Negation, not a product with -1.0 * 0.0: the same bits the old per-file code wrote.
glm::dvec3 signed_(const FileFrame& frame, glm::dvec3 v) {
  for (int i = 0; i < 3; ++i) {
    if (frame.sign[i] < 0) v[i] = -v[i];
  }
  return v;
}

glm::dvec3 fileAxes(const FileFrame& frame, glm::dvec3 w) {
  return signed_(frame, permuted(frame, w));
}

glm::dvec3 worldAxes(const FileFrame& frame, glm::dvec3 f) {
  return unpermuted(frame, signed_(frame, f));
}

}  // namespace

FileFrame::FileFrame(UpAxis up, double metersPerUnit_)
    // Y up: file (x, y, z) = world (x, z, -y), the inverse of zUpFromYUp (world_frame.h).
    : FileFrame(up == UpAxis::Y ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{0, 1, 2},
                up == UpAxis::Y ? std::array<double, 3>{1, 1, -1} : std::array<double, 3>{1, 1, 1},
                metersPerUnit_) {}

FileFrame::FileFrame(std::array<int, 3> axis_, std::array<double, 3> sign_, double metersPerUnit_)
    : axis(axis_), sign(sign_), determinant(1.0), metersPerUnit(metersPerUnit_) {
  const bool inRange =
      axis[0] >= 0 && axis[0] < 3 && axis[1] >= 0 && axis[1] < 3 && axis[2] >= 0 && axis[2] < 3;
  if (!inRange || axis[0] == axis[1] || axis[1] == axis[2] || axis[0] == axis[2]) {
    throw std::invalid_argument("FileFrame: the axes must be a permutation of 0, 1, 2");
  }
  // A cyclic order (0 1 2, 1 2 0, 2 0 1) is an even permutation.
  const bool even = (axis[0] + 1) % 3 == axis[1];
  determinant = (even ? 1.0 : -1.0) * sign[0] * sign[1] * sign[2];
}

glm::dvec3 filePointFromWorld(const FileFrame& frame, glm::dvec3 p) {
  return fileAxes(frame, p) / frame.metersPerUnit;
}

glm::dvec3 worldPointFromFile(const FileFrame& frame, glm::dvec3 p) {
  return worldAxes(frame, p * frame.metersPerUnit);
}

glm::dvec3 fileDirectionFromWorld(const FileFrame& frame, glm::dvec3 d) {
  return fileAxes(frame, d);
}

glm::dvec3 worldDirectionFromFile(const FileFrame& frame, glm::dvec3 d) {
  return worldAxes(frame, d);
}

glm::dvec3 fileHalfExtentsFromWorld(const FileFrame& frame, glm::dvec3 h) {
  return permuted(frame, h) / frame.metersPerUnit;
}

glm::dvec3 worldHalfExtentsFromFile(const FileFrame& frame, glm::dvec3 h) {
  return unpermuted(frame, h * frame.metersPerUnit);
}

double fileLengthFromWorld(const FileFrame& frame, double meters) {
  return meters / frame.metersPerUnit;
}

double worldLengthFromFile(const FileFrame& frame, double length) {
  return length * frame.metersPerUnit;
}

glm::dquat fileRotationFromWorld(const FileFrame& frame, const glm::dquat& q) {
  const glm::dvec3 v = fileAxes(frame, glm::dvec3(q.x, q.y, q.z));
  return withVectorPart(q, frame.determinant < 0 ? -v : v);
}

glm::dquat worldRotationFromFile(const FileFrame& frame, const glm::dquat& q) {
  const glm::dvec3 v = worldAxes(frame, glm::dvec3(q.x, q.y, q.z));
  return withVectorPart(q, frame.determinant < 0 ? -v : v);
}

glm::dmat4 worldToUnitFromFile(const FileFrame& frame, const glm::dmat4& fileToUnit) {
  // Columns of the world-from-file axis change A^T; GLM matrices are column-major.
  glm::dmat4 axes(0.0);
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 e(0.0);
    e[c] = 1.0;
    const glm::dvec3 column = worldAxes(frame, e);
    for (int r = 0; r < 3; ++r) axes[c][r] = column[r];
  }
  axes[3][3] = 1.0;
  // xFile = A xWorld / metersPerUnit: a linear map, translation 0.
  glm::dmat4 fileFromWorld = glm::transpose(axes);
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) fileFromWorld[c][r] /= frame.metersPerUnit;
  }
  return axes * fileToUnit * fileFromWorld;
}

FileFrame gltfFrame() { return FileFrame(UpAxis::Y, 1.0); }

FileFrame unityFrame() { return FileFrame({0, 2, 1}, {-1, 1, -1}, 1.0); }

FileFrame unrealFrame() { return FileFrame({0, 1, 2}, {1, -1, 1}, 0.01); }

}  // namespace probeproxy
