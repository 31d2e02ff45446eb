// The input format of surface_repair_fuzzer, shared with the regression test that replays its findings
// (tests/cpp/FuzzRegressionTest.cpp) and written by fuzz/make_seeds.py: a vertex count (1 byte), then each
// coordinate as one byte, a grid value (byte - 128) / 16 (so that vertices coincide, faces are coplanar and
// edges collinear often), or 0xFF followed by any 8-byte little-endian double (NaN, infinities, huge and tiny
// values); then faces until the input ends: a corner count (1 byte, modulo 9) and 2 bytes per corner, an
// index modulo two more than the vertex count (so that some are out of range). Missing bytes read as zero.
#pragma once

#include <cstdint>
#include <cstring>

#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh::fuzz {

inline PolygonSoup decodeSoup(const std::uint8_t* data, std::size_t size) {
  std::size_t position = 0;
  auto byte = [&]() -> std::uint8_t { return position < size ? data[position++] : 0; };
  PolygonSoup soup;
  soup.points.resize(byte());
  for (Vector3r& p : soup.points)
    for (int k = 0; k < 3; ++k) {
      const std::uint8_t tag = byte();
      if (tag != 0xFF) {
        p[k] = (int(tag) - 128) / 16.0;
        continue;
      }
      std::uint8_t bytes[8];
      for (std::uint8_t& b : bytes) b = byte();
      std::memcpy(&p[k], bytes, 8);
    }
  while (position < size) {
    std::vector<std::size_t>& face = soup.polygons.emplace_back(byte() % 9);
    for (std::size_t& corner : face) corner = (byte() | unsigned(byte()) << 8) % (soup.points.size() + 2);
  }
  return soup;
}

}  // namespace roundedmesh::fuzz
