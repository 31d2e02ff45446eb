// What every fuzz target shares: the line between an expected failure and a finding, the checks that a mesh
// the readers or the repair accepted is one a body can be made of, and the fuzzer's bytes as a source of
// numbers for the pair generator of tests/support/RandomPairs.hpp.
// Expected failures are std::invalid_argument and std::runtime_error (FileNotFound) with a message: the
// library's documented way of refusing an input. A finding is anything else: a crash, a hang or a leak
// (libFuzzer and the sanitizers report those), another exception type (uncaught, so libFuzzer reports it),
// an empty message, or a non-finite result accepted (finding(), which traps).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "pkg/io/MeshFile.hpp"
#include "pkg/meshing/BodyMesh.hpp"

namespace roundedmesh::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "roundedmesh fuzz finding: %s\n", what.c_str());
  __builtin_trap();
}

// Runs `attempt`; refusals with a message are fine, anything else escapes to libFuzzer.
template <class Attempt>
void refusalsOnly(Attempt attempt) {
  try {
    attempt();
  } catch (const std::invalid_argument& e) {
    if (std::strlen(e.what()) == 0) finding("std::invalid_argument without a message");
  } catch (const std::runtime_error& e) {
    if (std::strlen(e.what()) == 0) finding("std::runtime_error without a message");
  }
}

// What Mesh.load does after reading: a body with the curvature computed from the mesh (Eq. 1). It may refuse
// the surface; if it accepts it, everything the contact model reads must be finite and positive.
inline void requireUsableBody(const TriangleSurface& surface) {
  for (const Vector3r& v : surface.vertices)
    if (!v.allFinite()) finding("accepted a surface with a non-finite vertex");
  const BodyMesh body(surface, std::nullopt);
  if (!(std::isfinite(body.volume()) && body.volume() > 0)) finding("body volume " + std::to_string(body.volume()));
  if (!(body.principalMoments().allFinite() && (body.principalMoments().array() > 0).all()))
    finding("non-finite or non-positive principal moments");
  const RoundedMesh& shape = body.shape();
  if (!std::isfinite(shape.sphereBoundRadius())) finding("non-finite bounding radius");
  for (int t = 0; t < shape.triangleCount(); ++t) {
    const RoundedTriangle& r = shape.rounded(t);
    if (!(std::isfinite(r.radius) && r.radius > 0 && r.normal.allFinite() && r.sphereCentre.allFinite() &&
          std::isfinite(r.capHeight)))
      finding("triangle " + std::to_string(t) + " has a non-finite radius, normal or cap");
  }
}

// Reads the input as a mesh file of the given extension, as Mesh.load does (readMeshFile, then a body).
inline void fuzzMeshReader(const std::uint8_t* data, std::size_t size, const char* extension) {
  // One file per process, rewritten for every input: the readers take a path, and the extension picks one.
  static const std::string path = "/tmp/roundedmesh_fuzz_" + std::to_string(::getpid()) + "." + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) finding("cannot write " + path);
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  refusalsOnly([&] { requireUsableBody(readMeshFile(path)); });
}

// The fuzzer's bytes read in order, then zeros: a uniform value from 4 bytes (both ends reachable exactly), a
// direction from three of them (the z axis when they are all zero).
class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = v << 8 | (position_ < size_ ? data_[position_++] : 0);
    return v;
  }
  Real uniform(Real a, Real b) { return a + (b - a) * (u32() / Real(UINT32_MAX)); }
  Vector3r direction() {
    const Vector3r v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    return v.norm() > 0 ? Vector3r(v.normalized()) : Vector3r::UnitZ();
  }
  bool exhausted() const { return position_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

}  // namespace roundedmesh::fuzz
