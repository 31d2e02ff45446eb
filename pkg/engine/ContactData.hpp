// What changes every step: the states the engine reads (filled by the caller, in the order of the
// model's bodies and partners), the wrenches it produces (force [N] and torque [N m] about each body's own
// position, global frame), the counts and times of its stages, and what it keeps from step to step: the
// neighbour list of the broad phase and, per neighbouring pair of rounded bodies, its list of candidate
// triangle pairs, or of a rounded body and a Facet, the body's candidate triangles (Verlet lists, rebuilt only when
// the motion since their build exceeds their skin), and per
// neighbouring pair its tangential spring (TangentialSpring.hpp), which lasts as long as the pair touches.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <vector>

#include "pkg/engine/BodyState.hpp"
#include "pkg/engine/ContactModel.hpp"
#include "pkg/geom/FacetCandidates.hpp"
#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/CoulombFriction.hpp"
#include "pkg/law/NodeForces.hpp"
#include "pkg/law/TangentialSpring.hpp"

namespace roundedmesh {

// CPU seconds of the stages inside the pairs, summed over the pairs (and so over threads), measured under
// EngineOptions' timing = 'stages' (else 0).
struct PairStageTimes {
  Real lists = 0;        // candidate lists brought up to date (updateCandidates, updateFacetCandidates), near
                         // searches included
  Real nearSearch = 0;   // of which the near lists searched in the triangle trees (nearTrianglePairs)
  Real narrowPhase = 0;  // Ig2 over the candidates, or against a partner
  Real law = 0;          // Law2, node forces and friction (pairLoad)
  Real core = 0;         // the deep-overlap core (corePair)

  PairStageTimes& operator+=(const PairStageTimes& other);
};

// The funnel of one step, from body pairs down to triangle contacts, with the rejections of each test of
// the narrow phase in the order they run (Appendix B): facing check (Eq. B.5), sphere overlap (Eq. 10),
// projected circumcircle against the contact circle, empty polygon S, contact circle against S (h < a).
struct ContactStatistics {
  int bodyPairs = 0;           // pairs whose bounds overlap
  int touchingPairs = 0;       // pairs with at least one triangle contact
  NarrowPhaseCounts narrowPhase;  // triangle pairs (or triangle-partner pairs) tested, and their rejections
  int quadratureContacts = 0;  // triangle contacts integrated by quadrature
  int directContacts = 0;      // triangle contacts in the direct regime
  int exactContacts = 0;       // triangle contacts in the exact regime (closed form)
  int sphereContacts = 0;      // contacts of a sphere body with a sphere body or partner (one per pair)
  int coreContacts = 0;        // touching core spheres (CorePair.hpp): pairs overlapping past the Hertz range
  int slidingContacts = 0;     // triangle and sphere contacts sliding (Eq. 21, or all of a pair's whose spring slides)
  int neighbourRebuilds = 0;   // rebuilds of the broad phase's neighbour list
  int candidateRebuilds = 0;   // triangle-pair candidate lists rebuilt (from their pair's near list), and the
                               // candidate triangles of rounded bodies against Facets
  int nearRebuilds = 0;        // near lists rebuilt from the triangle trees
  long nearPairsScanned = 0;   // triangle pairs of the near lists scanned at the candidate lists' rebuilds
  PairStageTimes cpu;          // under timing = 'stages'

  ContactStatistics& operator+=(const ContactStatistics& other);
  int contacts() const { return quadratureContacts + directContacts + exactContacts + sphereContacts; }
};

// Wall-clock seconds of each stage of the last step.
struct StageTimes {
  Real broadPhase = 0;  // neighbour list and overlapping pairs
  Real pairs = 0;       // candidate lists, narrow phase and law over all pairs (in parallel)
  Real reduction = 0;   // pair wrenches summed per body
};

// A candidate of the broad phase: `body` against `other`, each an index into the model's bodies
// (< bodies.size()) or, past them, into its partners (- bodies.size()). `body` is a rounded body, or a sphere
// body when `other` is a partner too. `neighbour` is its entry
// in ContactData::neighbours (-1 for a pair resolved on its own, without the lists kept between steps).
struct BodyPair {
  int body;
  int other;
  int neighbour = -1;
};

// One triangle contact as resolvePair saw it, in the global frame, for listings and pictures.
struct TriangleContact {
  PressureGeom geom;         // body 1's frame, as Ig2 made it
  Vector3r point;            // c_eff [m]
  Vector3r normal;           // n12
  NormalLoad load;           // Fn [N] on body 2 along n12
  TangentialLoad friction;   // F_t [N] on body 2, global frame (with the spring: the contact's share of the pair's)
  std::array<Real, 3> nodeForces;         // Eq. 15 on body 1's triangle corners, along -n12 [N]
  std::array<Real, 3> partnerNodeForces;  // on body 2's triangle's corners, along n12, when it is a mesh
};

// What one pair's triangle contacts add up to, besides the wrenches (rm.contacts(), the energies of
// O.energy; doc/physics.md, "Energy"). Global frame.
struct PairSummary {
  Vector3r point = Vector3r::Zero();   // centre of pressure: the triangle contacts' points of application of their
                                       // normal forces, weighted by those forces [m]
  Vector3r normal = Vector3r::Zero();  // unit, along the sum of the normal forces, from the body to the other
  Real deepestOverlap = 0;             // the largest delta_eff (Eq. B.4) [m]
  Real depth = 0;                      // the largest delta_eff along `normal`, delta_eff (n12 . normal) [m]: how far
                                       // the bodies overlap; the deepest triangle contact can run through both at a
                                       // slant, longer than that (doc/physics.md, "Which triangle pairs touch")
  int triangleContacts = 0;
  bool sliding = false;                // the pair's spring slides, or (viscous law) any triangle contact (Eq. 21)
  Real elasticEnergy = 0;              // sum of the triangle contacts' elastic energies (NormalLoad), and the
                                       // energy of the pair's tangential spring [J]
  Real dampingPower = 0;               // sum of (Fn - F_elastic) ddelta_s/dt at the centre of pressure:
                                       // dissipated by normal damping [W]
  Real frictionPower = 0;              // dissipated by friction [W]: sum of -F_t . v_t (viscous law), or the
                                       // spring's SpringLoad::dissipatedPower

  // Adds one contact's overlap, elastic energy (NormalLoad::elasticEnergy, doc/physics.md "Energy") and normal
  // damping.
  void add(const PressureGeom& geom, const NormalLoad& load) {
    deepestOverlap = std::max(deepestOverlap, geom.effectiveOverlap);
    elasticEnergy += load.elasticEnergy;
    dampingPower += (load.force - load.elasticForce) * load.overlapRate;
  }
};

// One pair of a step as the stop rules see it (StopRules.hpp).
struct PairRecord {
  int body, other;         // engine indices, as in BodyPair
  Real overlap = 0;        // how far the bodies overlap [m] (PairSummary::depth), 0 if they did not touch
  bool flat = false;       // whether the other side is a Wall, Plane, Facet or Box
  Real side = 0;           // then: where the body's centre is against it [m] (StopRules.cpp, faceSide)
  Vector3r position = Vector3r::Zero();  // the body's centre [m]
  Vector3r point = Vector3r::Zero();     // the pair's centre of pressure [m] (PairSummary::point), if they touched
  Real closing = 0;        // how fast the two sides approach there along the pair's normal [m/s] (< 0: they part)
};

// Why a step must not be kept (StopRules.hpp): the body's centre crossed the other side's face since the last
// step, or the pair overlaps by more than the model's stopOverlap of its size and the overlap grew.
enum class StopCause { CentreCrossed, Overlap };
struct StopReason {
  StopCause cause;
  int body, other;  // engine indices
  Real overlap;     // how far the bodies overlap [m] (PairSummary::depth; 0 if they no longer touch)
  Real size;        // the size the overlap is measured by [m]
  Vector3r point;   // where: the pair's centre of pressure [m], or the body's centre if they no longer touch
};

// The outcome of one pair: the wrench on each side (global frame, torque about each one's position).
struct PairResult {
  Wrench onBody, onOther;
  PairSummary summary;
  ContactStatistics statistics;
};

// The candidate triangles of a rounded body against a Facet partner (FacetCandidates), with what they were made for:
// the facet's shape and edge radius, the body's side of it, and the body's pose in the facet's frame. They hold while
// every point of the body's triangle tree moves by at most `skin` relative to the facet from that pose, and its centre
// by less than `sideClearance`.
struct FacetList {
  bool built = false;
  Quaternionr rotation = Quaternionr::Identity();  // the body's frame in the facet body's, at the build
  Vector3r translation = Vector3r::Zero();
  Real skin = 0;           // [m]
  Real sideClearance = 0;  // how far the body's centre may move before its side can change (facetSide) [m]
  int age = 0;             // steps since the build
  std::shared_ptr<const FacetWeld> weld;  // the facet's shape at the build (held, so that no other takes its address)
  std::array<Vector3r, 3> vertices;
  Real edgeRadius = 0;  // [m]
  FacetCandidates candidates;
};

// Candidate triangle pairs (s of the body, t of the other body) of two rounded bodies, in two levels
// (TrianglePairCandidates.hpp): `near`, from the triangle trees, holds every pair that can be in contact, with
// an effective overlap of at most nearDepth, while every point of the other body moves by at most nearSkin
// relative to the body from the pose nearRotation, nearTranslation; `pairs`, taken from `near`, does the same
// for `skin`, `depth` and its own pose.
struct CandidateList {
  bool built = false;
  Quaternionr rotation = Quaternionr::Identity();  // the other body's frame in the body's, at the build
  Vector3r translation = Vector3r::Zero();
  Real skin = 0;     // [m]
  Real depth = 0;    // [m]
  int age = 0;       // steps since the build
  Real deepest = 0;  // the deepest effective overlap of the pair at its last evaluation [m]
  std::vector<std::array<int, 2>> pairs;

  Quaternionr nearRotation = Quaternionr::Identity();
  Vector3r nearTranslation = Vector3r::Zero();
  Real nearSkin = 0;   // [m]; 0: not built
  Real nearDepth = 0;  // [m]
  std::vector<std::array<int, 2>> near;

  std::unique_ptr<FacetList> facet;  // a rounded body's against a Facet partner instead, made on first use
};

// Where a body or partner is, seen from this process, when YADE's MPI decomposition (yade.mpy) splits the scene
// over processes (doc/architecture.md, "Many processes"). In one process every body is Own.
enum class Residence : unsigned char {
  Own,     // this process moves it
  Master,  // owned by the master process (rank 0), which receives its forces from here (a Wall, a Box, a Facet)
  Image,   // another worker owns it; this process holds its copy, with the owner's state
  Absent,  // not in this process
};

struct ContactData {
  std::vector<BodyState> bodyStates;
  std::vector<BodyState> partnerStates;
  // Masses [kg] and principal moments of inertia [kg m^2] (a rounded body's in its mesh's frame) for the time-step
  // check (CriticalTimeStep.hpp, stabilityLimit): a partner's are 0 unless it moves under forces; 0 (the default)
  // puts no limit.
  std::vector<Real> bodyMasses, partnerMasses;
  std::vector<Vector3r> bodyInertias, partnerInertias;
  // What the time step was last found stable for (ContactStep.hpp, checkTimeStep); NaN: nothing yet.
  struct CheckedTimeStep {
    Real timeStep = std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real> bodyMasses, partnerMasses;
    std::vector<Vector3r> bodyInertias, partnerInertias;
  } checkedTimeStep;
  // The clump each body and partner belongs to (YADE's clumpId), -1 for none: members of one clump do not
  // touch each other.
  std::vector<int> bodyClumps;
  std::vector<int> partnerClumps;
  std::vector<Wrench> bodyWrenches;
  std::vector<Wrench> partnerWrenches;
  // Bodies, then partners (engine indices). A pair is computed where one of its sides is Own and neither is
  // Absent, so a pair of two workers' bodies on both workers (each applies its own side's wrench, as YADE's own
  // engines do under yade.mpy) and a pair with a master's body once; wrenches go to Own and Master bodies.
  std::vector<Residence> residences;
  ContactStatistics statistics;
  StageTimes times;

  // Broad phase: the neighbour list (pairs whose bounds, grown by half the skin, overlapped at its build),
  // the world boxes it was built for, grown by half the skin, and each neighbour's candidate list.
  std::vector<BodyPair> neighbours;
  std::vector<AlignedBox3r> neighbourBoxes;
  std::vector<CandidateList> candidateLists;
  std::vector<TangentialSpring> springs;  // one per neighbour; reset when the pair does not touch
  // Springs given by restoreSprings, sorted by pair: handed to their pairs by the next neighbour-list build.
  std::vector<std::pair<BodyPair, TangentialSpring>> restoredSprings;
  Real timeStep = 0;  // [s] since the last step: how far the springs move (0: no spring moves)

  std::vector<AlignedBox3r> boxes;                // scratch: the world boxes of this step
  std::vector<BodyPair> pairs;                    // pairs whose bounds overlap this step
  std::vector<PairResult> pairResults;            // one per pair
  // Every triangle contact of each pair, kept only when asked for (for the forces per triangle of the export).
  bool keepTriangleContacts = false;
  std::vector<std::vector<TriangleContact>> pairContacts;
  std::vector<std::vector<PressureGeom>> geoms;   // scratch: one per thread

  // The stop rules (StopRules.hpp): this step's pairs, and those of the last step kept (valid if `kept`).
  std::vector<PairRecord> pairRecords, keptRecords;
  bool kept = false;

  // The state and clump of an engine index: a body's, or past them a partner's.
  const BodyState& state(int index) const {
    const int bodyCount = static_cast<int>(bodyStates.size());
    return index < bodyCount ? bodyStates[index] : partnerStates[index - bodyCount];
  }
  bool present(int index) const { return residences[index] != Residence::Absent; }
  bool computesPair(int index, int other) const {
    return present(index) && present(other) &&
           (residences[index] == Residence::Own || residences[other] == Residence::Own);
  }
  bool appliesWrench(int index) const {
    return residences[index] == Residence::Own || residences[index] == Residence::Master;
  }
  int clump(int index) const {
    const int bodyCount = static_cast<int>(bodyClumps.size());
    return index < bodyCount ? bodyClumps[index] : partnerClumps[index - bodyCount];
  }

  // Sizes every array for `model`; states and masses are left for the caller to fill.
  void resize(const ContactModel& model);

  // Every active spring, with its pair (engine indices, the pair's own order), sorted by pair.
  std::vector<std::pair<BodyPair, TangentialSpring>> activeSprings() const;
  // Replaces every spring by `springs` (as activeSprings gives them): the lists kept between steps are dropped and
  // the next step builds them again, handing each pair its spring (a pair given the other way round gets its spring
  // seen from the other side).
  void restoreSprings(std::vector<std::pair<BodyPair, TangentialSpring>> springs);
};

}  // namespace roundedmesh
