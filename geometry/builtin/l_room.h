#pragma once
// A closed L-shaped room, the analytic concave level: a square corner room with two arms of
// the same width, one along +x and one along +y, faces wound to face inwards. With arm length 0
// it is a box; the longer the arms, the more of the room's bounding box is not room.
//
//   y
//   ^  +----+
//   |  | y  |          corner room [0, w] x [0, w], arms [w, w + a] x [0, w] and
//   |  | arm|          [0, w] x [w, w + a], floor at z = 0, ceiling at z = h
//   |  +----+-------+
//   |  |    | x arm |
//   |  +----+-------+--> x

#include "geometry/level/level_mesh.h"

namespace probeproxy {

struct LRoomSize {
  double widthMeters = 4.0;   // w: the corner room's side and each arm's width
  double armMeters = 6.0;     // a: how far each arm reaches past the corner room (>= 0)
  double heightMeters = 3.0;  // h
};

LevelMesh lRoom(const LRoomSize& size);

}  // namespace probeproxy
