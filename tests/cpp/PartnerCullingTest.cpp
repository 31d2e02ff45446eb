// The culling of the Facets' Ig2 (Ig2_RoundedMesh_Facet_PressureGeom, faceGeometry, featureGeometry): the boxes of the
// body's triangle tree tested against the face's plane and the region of it the facet keeps, its strips' reach, and
// the root box first. Culling only saves work: it must lose no contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <vector>

#include "bench/RecordedScene.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

using test::at;
using Corners = std::array<Vector3r, 3>;

const HertzMaterial kFloor{5e6, 0.4, 2000, 1e-3, 0};

// A floor of 8 facets ([-2 L, 2 L]^2, z = 0) with a thin plate of two facets standing on it across x = 0, 4 L long
// and 2.5 L tall: the floor's panel with its seams, the plate's free rims with their lips, and its foot.
std::vector<Corners> floorWithPlate(Real L) {
  std::vector<Corners> facets;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const Real x = 2 * L * (i - 1), y = 2 * L * (j - 1);
      const Vector3r a(x, y, 0), b(x + 2 * L, y, 0), c(x + 2 * L, y + 2 * L, 0), d(x, y + 2 * L, 0);
      facets.push_back({a, b, c});
      facets.push_back({a, c, d});
    }
  const Vector3r a(0, -2 * L, 0), b(0, 2 * L, 0), c(0, 2 * L, 2.5 * L), d(0, -2 * L, 2.5 * L);
  facets.push_back({a, b, c});
  facets.push_back({a, c, d});
  return facets;
}

struct Touch {
  Wrench wrench;
  size_t contacts;
};

Touch onFacets(const RoundedBody& body, const BodyState& state, const std::vector<Corners>& facets) {
  // The closed forms: the quadrature's error depends on the contact plane's in-plane axes, which a turned mesh turns.
  EngineOptions exact;
  exact.pressure.regime = RegimeChoice::Exact;
  const PairEvaluation e = surfaceContact(body, state, test::facetPartners(facets, kFloor),
                                          std::vector<BodyState>(facets.size(), at(Vector3r::Zero())), exact, true);
  return {e.onFirst, e.contacts.size()};
}

// S1's gummy bear around the plate, in 200 random orientations and places: pressed 0.01 of its size further than it
// first touches, coming down onto the floor across the panel's seams beside the plate, or sideways onto the plate's
// face, the ball that holds it clear of the floor and the plate's rims (whose lips' contacts are decided with the
// body's distance field, sampled on a grid in the body's frame: a turned mesh samples it elsewhere). The same
// bear with its mesh turned in its own frame (RoundedMesh::transformed), placed so that its surface is where it was,
// has a tree of other boxes, culled differently: it must meet the same contacts, as many, its force and torque the
// same to round-off, the pressure integrated in closed form, which does not depend on the plane's axes. The turned
// vertices move the overlaps by about 1e-16 of the body's size, 1e-14 of a 0.01 overlap, but a contact whose circle
// barely reaches S (h close to a) magnifies that: up to 2e-9 of a light touch's torque measured; 1e-7 allowed. A
// contact lost to either culling changes the count, and the force by its share among a few dozen.
TEST(PartnerCulling, ATurnedTreeMeetsTheSameContacts) {
  const RoundedBody bear = loadRecordedScene().model.bodies[0];
  const Quaternionr turn(Eigen::AngleAxis<Real>(0.7, Vector3r(1, -2, 0.5).normalized()));
  RoundedBody turned = bear;
  turned.mesh = std::make_shared<const RoundedMesh>(bear.mesh->transformed(turn.toRotationMatrix(), Vector3r::Zero()));
  std::mt19937 random(23);
  std::normal_distribution<Real> normal;
  std::uniform_real_distribution<Real> uniform(0, 1);
  Real bound = 0;  // the ball about the bear's centre that holds its rounded surface [m]
  for (const Vector3r& x : bear.mesh->vertices()) bound = std::max(bound, x.norm() + bear.mesh->maxCapHeight());
  const std::vector<Corners> facets = floorWithPlate(bound);
  int touching = 0, onPlate = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Quaternionr orientation =
        Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
    // Down onto the floor beside the plate, or sideways onto the plate's face, clear of the floor, its rims and ends.
    const bool sideways = uniform(random) < 0.3;
    const Real beside = bound * (1 + uniform(random)) * (uniform(random) < 0.5 ? -1 : 1);
    const Vector3r position = sideways ? Vector3r(1.05 * bound, bound * (2 * uniform(random) - 1), 1.25 * bound)
                                       : Vector3r(beside, bound * (4 * uniform(random) - 2), 1.05 * bound);
    const Vector3r step = (sideways ? Vector3r(-1, 0, 0) : Vector3r(0, 0, -1)) * 0.005 * bound;
    BodyState state = at(position, orientation);
    auto touches = [&] { return onFacets(bear, state, facets).contacts > 0; };
    // Ten steps at a time to the first touch, then back and one at a time: the first touch within a step.
    int strides = 0;
    while (!touches() && strides++ < 40) state.position += 10 * step;
    if (strides == 0 || strides > 40) continue;  // placed touching, or passing by
    state.position -= 10 * step;
    while (!touches()) state.position += step;
    state.position += 2 * step;  // 0.01 of its size further
    const Touch first = onFacets(bear, state, facets);
    const Touch second = onFacets(turned, at(state.position, state.orientation * turn.conjugate()), facets);
    ASSERT_GT(first.wrench.force.norm(), 0) << "trial " << trial;
    ++touching;
    onPlate += std::abs(first.wrench.force.z()) < 0.9 * first.wrench.force.norm();
    EXPECT_LT((second.wrench.force - first.wrench.force).norm(), 1e-7 * first.wrench.force.norm()) << "trial " << trial;
    EXPECT_LT((second.wrench.torque - first.wrench.torque).norm(),
              1e-7 * first.wrench.force.norm() * bound)
        << "trial " << trial;
    EXPECT_EQ(second.contacts, first.contacts) << "trial " << trial;
  }
  // Most poses touch; many of them the plate.
  EXPECT_GT(touching, 150);
  EXPECT_GT(onPlate, 30);
}

}  // namespace
}  // namespace roundedmesh
