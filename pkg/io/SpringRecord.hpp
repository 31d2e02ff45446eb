// The tangential springs of a scene as text that YADE keeps in O.tags (doc/architecture.md, "What a saved scene
// keeps"), so that O.save / O.load go on with the contacts' friction as it was. The record is base64 (RFC 4648,
// with padding) of the bytes "RMSPRING1" followed, per spring, by the YADE ids of its pair (two int32, the pair's
// own order) and eight doubles: displacement (3), twist, normal (3), energy (TangentialSpring.hpp), little-endian.
// decodeSprings throws std::invalid_argument for text that is not such a record (damaged or cut short).
#pragma once

#include <string>
#include <vector>

#include "pkg/law/TangentialSpring.hpp"

namespace roundedmesh {

struct SpringEntry {
  int id1, id2;  // YADE ids
  TangentialSpring spring;
};

std::string encodeSprings(const std::vector<SpringEntry>& springs);
std::vector<SpringEntry> decodeSprings(const std::string& record);

}  // namespace roundedmesh
