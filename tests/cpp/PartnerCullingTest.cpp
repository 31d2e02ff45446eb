// The culling of the Facets' Ig2 (Ig2_RoundedMesh_Facet_PressureGeom, faceGeometry, featureGeometry): the boxes of the
// body's triangle tree tested against the face's plane and the region of it the facet keeps, its strips' reach, and
// the root box first; and the candidate triangles a pair keeps from step to step (FacetCandidates, FacetList), found
// with a margin. Culling only saves work: it must lose no contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <vector>

#include "bench/RecordedScene.hpp"
#include "pkg/engine/CandidateLists.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/engine/WeldedFacets.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/geom/TriangleEdgeGeom.hpp"
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


// The floor and plate, with a ridge of four facets on the floor beside the plate (its apex 0.4 L high at x = 1.5 L,
// its slopes reaching the floor at x = L and 2 L), welded, as a scene's partners at rest in the world's frame. The
// ridge's apex is a fold, convex from above: a body beyond it is on its far face's other side (facetSide).
ContactModel weldedFloorPlateAndRidge(const RoundedBody& body, Real L) {
  std::vector<Corners> facets = floorWithPlate(L);
  const Vector3r a(L, -2 * L, 0), b(1.5 * L, -2 * L, 0.4 * L), c(2 * L, -2 * L, 0), y(0, 4 * L, 0);
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, c}}) {
    facets.push_back({from, to, to + y});
    facets.push_back({from, to + y, from + y});
  }
  ContactModel model;
  model.bodies.push_back(body);
  model.partners = test::facetPartners(facets, kFloor);
  weldFacetPartners(model, std::vector<BodyState>(model.partners.size(), at(Vector3r::Zero())));
  return model;
}

// A welded facet of `model`, at rest in the world's frame, placed in the frame of a body in `state`.
PlacedFacet placedIn(const ContactModel& model, int partner, const BodyState& state) {
  const Matrix3r R_BW = state.orientation.toRotationMatrix().transpose();
  return placeFacet(std::get<Facet>(model.partners[partner].shape), R_BW, -(R_BW * state.position));
}

// The largest distance a point of the box moves from one pose of the body to the other [m]: the displacement of a
// rigid motion is affine in the point, so its norm is largest at a corner.
Real largestMove(const AlignedBox3r& box, const BodyState& from, const BodyState& to) {
  Real largest = 0;
  for (int c = 0; c < 8; ++c) {
    const Vector3r x = box.corner(static_cast<AlignedBox3r::CornerType>(c));
    largest = std::max(largest, ((to.orientation * x + to.position) - (from.orientation * x + from.position)).norm());
  }
  return largest;
}

// Whether two Ig2 outputs are the same contacts, bit for bit, in the same order.
bool sameContacts(const std::vector<PressureGeom>& a, const std::vector<PressureGeom>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k) {
    const PressureGeom &x = a[k], &y = b[k];
    if (x.triangle != y.triangle || x.normal != y.normal || x.centre != y.centre || x.radius != y.radius ||
        x.sphereOverlap != y.sphereOverlap || x.effectiveOverlap != y.effectiveOverlap ||
        x.effectivePoint != y.effectivePoint || x.overlapRate != y.overlapRate || x.slip != y.slip ||
        x.polygon.size() != y.polygon.size())
      return false;
    for (int i = 0; i < x.polygon.size(); ++i)
      if (x.polygon[i] != y.polygon[i]) return false;
  }
  return true;
}

bool sameCounts(const NarrowPhaseCounts& a, const NarrowPhaseCounts& b) {
  return a.candidates == b.candidates && a.notFacing == b.notFacing && a.noOverlap == b.noOverlap &&
         a.outsideCircle == b.outsideCircle && a.emptyPolygon == b.emptyPolygon &&
         a.beyondContactCircle == b.beyondContactCircle && a.throughBody == b.throughBody;
}

// A random unit quaternion.
Quaternionr randomTurn(std::mt19937& random) {
  std::normal_distribution<Real> normal;
  return Quaternionr(normal(random), normal(random), normal(random), normal(random)).normalized();
}

// The tree's queries visit every triangle whose own box passes the culling, whether or not the boxes of the nodes
// above it would pass the triangles' test: the reach of a strip is tested on a box's circumscribed ball, and a ball
// of a box inside a node reaches out of the node's ball (before the nodes had their own test, the drum of scene S7
// lost some 5 such triangles per step). Each query is compared with the test applied to every triangle's box, on S1's
// bear, for faces and strips in 300 random places about it, without a margin and with one.
TEST(PartnerCulling, TheQueriesVisitEveryTriangleWhoseBoxPasses) {
  const RoundedBody bear = loadRecordedScene().model.bodies[0];
  const RoundedMesh& mesh = *bear.mesh;
  const Real bound = mesh.sphereBoundRadius();
  std::mt19937 random(5);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  auto near = [&]() -> Vector3r { return Vector3r(uniform(random), uniform(random), uniform(random)) * 1.2 * bound; };
  const TriangleTree& tree = mesh.tree();
  long facesVisited = 0, stripsVisited = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Real margin = trial % 2 == 0 ? 0 : 0.05 * bound;
    // A face: a random plane's triangle of the body's size, its outline about the foot of a random point.
    ContactFace face;
    face.origin = near();
    face.normal = Vector3r(uniform(random), uniform(random), uniform(random)).normalized();
    face.tangent1 = face.normal.unitOrthogonal();
    face.tangent2 = face.normal.cross(face.tangent1);
    const FaceOutline outline({Vector2r(-bound, -bound), Vector2r(bound, -0.5 * bound), Vector2r(0, bound)});
    face.faceOutline = &outline;
    face.sheet = trial % 3 != 0;
    std::vector<int> listed;
    faceCandidates(mesh, face, margin, listed);
    const FaceReach reach(mesh, face, margin);
    std::vector<int> passing;
    for (int t = 0; t < mesh.triangleCount(); ++t)
      if (reach(tree.triangleBox(t))) passing.push_back(t);
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, passing) << "face, trial " << trial;
    facesVisited += static_cast<long>(passing.size());
    // A strip: a random segment near the body, with the test written out again here.
    const RoundedFeature strip{near(), near(), 0.02 * bound, {}};
    featureCandidates(mesh, strip, margin, listed);
    passing.clear();
    const Vector3r along = strip.end - strip.start;
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      const AlignedBox3r& box = tree.triangleBox(t);
      const Real s = std::clamp((box.center() - strip.start).dot(along) / along.squaredNorm(), Real(0), Real(1));
      const Real reachOf = featureReach(mesh, strip.radius) + margin + 0.5 * box.sizes().norm();
      if ((box.center() - strip.start - s * along).squaredNorm() <= reachOf * reachOf) passing.push_back(t);
    }
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, passing) << "strip, trial " << trial;
    stripsVisited += static_cast<long>(passing.size());
  }
  // The places reach the body: many triangles pass.
  EXPECT_GT(facesVisited, 300 * mesh.triangleCount() / 10);
  EXPECT_GT(stripsVisited, 300 * 10);
}

// Kept candidates lose nothing. S1's bear about the floor, plate and ridge of welded facets, in 300 random poses
// (about the plate's top, the ridge's apex, or on the floor where the plate cuts into it; touching them in many), its
// candidates against each facet made with a margin of 0.02 of its size; then moved and turned at random so that no
// point of its tree's root box moves by more than the margin, on the same side of the facet: the Ig2 over the
// candidates finds the same contacts as over the whole tree, bit for bit, in the same order, and tests as many
// triangles with the same outcomes; a centre moved by less than its clearance (facetSide) stays on its side. Moved
// toward the floor by three margins instead, the candidates miss contacts (the test can fail).
TEST(PartnerCulling, KeptCandidatesFindWhatTheWholeTreeFinds) {
  const RoundedBody bear = loadRecordedScene().model.bodies[0];
  const RoundedMesh& mesh = *bear.mesh;
  const Real bound = mesh.sphereBoundRadius();
  const ContactModel model = weldedFloorPlateAndRidge(bear, bound);
  const AlignedBox3r& root = mesh.tree().nodes().front().box;
  const Real margin = 0.02 * bound, edgeRadius = edgeRadiusFor(model.partners[0], bear.equivalentRadius);
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> uniform(0, 1);
  int compared = 0, touching = 0, listedWithout = 0, missed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Real where = uniform(random), y = bound * (3 * uniform(random) - 1.5);
    const Vector3r position =
        where < 0.25  ? Vector3r(bound * (0.6 * uniform(random) - 0.3), y, bound * (2.2 + 0.6 * uniform(random)))
        : where < 0.5 ? Vector3r(bound * (1.5 + 1.2 * uniform(random) - 0.6), y, bound * (1.1 + 0.4 * uniform(random)))
                      : Vector3r(bound * (2 * uniform(random) - 1), y, bound * (0.9 + 0.3 * uniform(random)));
    const BodyState from = at(position, randomTurn(random));
    // A motion within the margin: a random offset and turn, scaled down until the root box moves by at most u margins.
    const Vector3r offset = Vector3r(uniform(random) - 0.5, uniform(random) - 0.5, uniform(random) - 0.5).normalized();
    const Vector3r axis = Vector3r(uniform(random) - 0.5, uniform(random) - 0.5, uniform(random) - 0.5).normalized();
    auto moved = [&](Real scale) {
      return at(from.position + scale * offset, from.orientation * Quaternionr(Eigen::AngleAxis<Real>(scale / bound, axis)));
    };
    const Real u = uniform(random);
    Real scale = margin;
    while (largestMove(root, from, moved(scale)) > u * margin) scale *= 0.9;
    const BodyState to = moved(scale);
    const BodyState past = at(from.position - Vector3r(0, 0, 3 * margin), from.orientation);
    for (size_t f = 0; f < model.partners.size(); ++f) {
      const PlacedFacet before = placedIn(model, static_cast<int>(f), from);
      Real clearance;
      FacetCandidates candidates;
      facetCandidates(mesh, before, facetSide(before, &clearance), edgeRadius, margin, candidates);
      auto compare = [&](const BodyState& state, bool within) {
        const PlacedFacet now = placedIn(model, static_cast<int>(f), state);
        const bool sideKept = facetSide(now) == candidates.side;
        // Within its clearance the centre stays on its side.
        if ((state.position - from.position).norm() < clearance) {
          EXPECT_TRUE(sideKept) << "trial " << trial;
        }
        if (!sideKept) return;  // the engine makes them again
        std::vector<PressureGeom> all, kept;
        NarrowPhaseCounts allCounts, keptCounts;
        Ig2_RoundedMesh_Facet_PressureGeom(mesh, now, edgeRadius, RelativeMotion(), GeomOutput(all, &allCounts));
        Ig2_RoundedMesh_Facet_PressureGeom(mesh, now, edgeRadius, RelativeMotion(), GeomOutput(kept, &keptCounts),
                                           CurvatureModel::Mean, &candidates);
        if (!within) {
          missed += kept.size() < all.size();
          return;
        }
        ++compared;
        touching += !all.empty();
        listedWithout += all.empty() && !candidates.empty();
        EXPECT_TRUE(sameContacts(kept, all)) << "trial " << trial << ", facet " << f;
        EXPECT_TRUE(sameCounts(keptCounts, allCounts)) << "trial " << trial << ", facet " << f;
      };
      compare(to, true);
      compare(past, false);
    }
  }
  EXPECT_GT(compared, 2000);
  EXPECT_GT(touching, 100);       // the bear touches a facet
  EXPECT_GT(listedWithout, 100);  // and comes within the margin of one it does not touch
  EXPECT_GT(missed, 10);
}

// The engine keeps a facet pair's candidates while the body moves within their skin and makes them again when it
// leaves it, crosses to the facet's other side or the facet changes; every step finds what the pair finds without
// them. S1's bear moves 450 steps of about 0.04 mm and 0.03 degrees relative to the facets: across the plate's top
// edge, which cuts into it (its centre crosses the plate's plane: the plate's facets see it go to their other side);
// down the middle of the ridge's far face, its farthest vertex that way 0.3 mm into it, near the plane of the ridge's
// other face; along the floor, its lowest vertex 0.3 mm below it, then 1.3 mm once the floor is raised by 1 mm. The whole scene turns and moves meanwhile, as a drum's wall does (the facets' states move with it). Each
// pair's result with its candidates kept, step after step, equals the pair resolved afresh, bit for bit.
TEST(PartnerCulling, APairKeepsItsCandidatesAcrossSteps) {
  const RoundedBody bear = loadRecordedScene().model.bodies[0];
  const Real bound = bear.mesh->sphereBoundRadius();
  ContactModel model = weldedFloorPlateAndRidge(bear, bound);
  ContactData data;
  data.resize(model);
  data.timeStep = 1e-5;
  std::vector<CandidateList> lists(model.partners.size());
  std::vector<PressureGeom> scratch;
  const int legSteps = 150, steps = 3 * legSteps;
  const Vector3r axis = Vector3r(1, 2, 3).normalized();
  auto turn = [&](int step) { return Quaternionr(Eigen::AngleAxis<Real>(5e-4 * step, axis)); };
  // The ridge's far face: its outward normal and its slope's direction.
  const Vector3r farNormal = Vector3r(0.8, 0, 1).normalized(), downFar = Vector3r(1, 0, -0.8).normalized();
  int touchingSteps = 0, flips = 0;
  long rebuilds = 0;
  for (int step = 0; step < steps; ++step) {
    const int leg = step / legSteps;
    const Real s = static_cast<Real>(step % legSteps) / legSteps - 0.5;  // -0.5 to 0.5 along each leg
    Vector3r position = leg == 0 ? Vector3r(0.1 * bound * s, 0.3 * bound, 2.3 * bound) : Vector3r(-1.2 * bound, 0.1 * bound * s, 0);
    const Quaternionr orientation = turn(step);
    if (leg == 1) {
      // On the far face, its farthest vertex that way 0.3 mm into the face's middle, moved down the slope.
      Vector3r deepest = Vector3r::Zero();
      for (const Vector3r& vertex : bear.mesh->vertices())
        if (farNormal.dot(orientation * vertex) < farNormal.dot(deepest)) deepest = orientation * vertex;
      const Vector3r middle(1.75 * bound, -0.2 * bound, 0.2 * bound);
      position = middle - deepest - 3e-4 * farNormal + 0.1 * bound * s * downFar;
    }
    if (leg == 2) {
      if (step == 2 * legSteps + legSteps / 2) {  // the floor raised by 1 mm and welded anew: every list is made again
        for (int f = 0; f < 8; ++f)
          for (Vector3r& corner : std::get<Facet>(model.partners[f].shape).vertices) corner.z() += 1e-3;
        weldFacetPartners(model, data.partnerStates);
      }
      Real lowest = 0;
      for (const Vector3r& v : bear.mesh->vertices()) lowest = std::min(lowest, (orientation * v).z());
      position.z() = -lowest - 3e-4;
    }
    // The scene in a frame that turns by 0.03 degrees per step about a line 3 sizes below it, as a drum's wall does.
    const Quaternionr frame(Eigen::AngleAxis<Real>(5e-4 * step, Vector3r::UnitY()));
    const Vector3r pivot(0, 0, -3 * bound);
    auto placed = [&](const Vector3r& x) -> Vector3r { return pivot + frame * (x - pivot); };
    data.bodyStates[0] = at(placed(position), frame * orientation);
    data.bodyStates[0].velocity = Vector3r(0.1, -0.2, 0.05);
    data.bodyStates[0].angularVelocity = Vector3r(1, 0, -2);
    for (BodyState& state : data.partnerStates) state = at(placed(Vector3r::Zero()), frame);
    bool touches = false;
    for (size_t p = 0; p < model.partners.size(); ++p) {
      const BodyPair pair{0, 1 + static_cast<int>(p), static_cast<int>(p)};
      const int sideBefore = lists[p].facet ? lists[p].facet->candidates.side : -1;
      TangentialSpring keptSpring, freshSpring;
      const PairResult kept = resolvePair(model, data, pair, scratch, nullptr, &lists[p], &keptSpring);
      const PairResult alone = resolvePair(model, data, pair, scratch, nullptr, nullptr, &freshSpring);
      rebuilds += kept.statistics.candidateRebuilds;
      flips += sideBefore >= 0 && lists[p].facet->candidates.side != sideBefore;
      EXPECT_EQ(kept.onBody.force, alone.onBody.force) << "step " << step << ", facet " << p;
      EXPECT_EQ(kept.onBody.torque, alone.onBody.torque) << "step " << step << ", facet " << p;
      EXPECT_TRUE(sameCounts(kept.statistics.narrowPhase, alone.statistics.narrowPhase)) << "step " << step;
      touches = touches || alone.summary.triangleContacts > 0;
    }
    touchingSteps += touches;
  }
  EXPECT_GT(touchingSteps, steps * 9 / 10);
  EXPECT_GE(flips, 2);  // the plate's two facets
  // Made again every few steps, not at every step of every pair.
  EXPECT_GT(rebuilds, static_cast<long>(model.partners.size()) + 10);
  EXPECT_LT(rebuilds, static_cast<long>(model.partners.size()) * steps / 3);
}
}  // namespace
}  // namespace roundedmesh
