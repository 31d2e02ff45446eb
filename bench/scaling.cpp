// Google Benchmark of how the contact step's cost grows with the number of bodies and of contact primitives (the
// paper's Section 3.4 and Fig. 12: contact detection and contact resolution against N_prim), no YADE:
//   BM_Lattice/shape/side/motion  side^3 bodies of radius 5 mm on a simple cubic lattice, each overlapping its six
//                                 neighbours by 0.5 % of the radius, turned at random (seeded); shape 0: perfect
//                                 spheres (the engine's sphere bodies), 1-4: icospheres of 12, 42, 162 and 642 nodes
//                                 with exact curvature; motion 0: at rest (contact resolution, the lists checked
//                                 and kept), 1: rattling, every body moving and turning by up to a quarter of the
//                                 overlap with a period of 10 steps (the lists rebuilt as the bodies move)
//   BM_TiledS1/tiles/motion/threads  the settled S1 packing of 250 gummy bears (bench/data) repeated `tiles` times side
//                                 by side on the floor, the side walls dropped (250 to 8,000 bears); motion 0: the
//                                 settled poses again and again, 1: the recorded shaking, every tile alike, forth
//                                 and back (the lists rebuilt as the bears move); one thread, or each of
//                                 ROUNDEDMESH_BENCH_THREADS (comma-separated) on larger machines
// Counters per step: bodies, primitives (triangles, or spheres), body pairs, contacts, ns per body-step, the broad
// phase's and the pairs' ms, and bytes: the engine's per-step data (lists, pairs, springs, records) per body, and the
// mesh, shared by every body of a shape.
//   build/bench/roundedmesh_scaling_bench --benchmark_format=json > scaling.json   (scripts/benchmarks/scaling.py
//   runs it and writes doc/scaling.md's table, CSV and plots)
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "bench/RecordedScene.hpp"
#include "bench/ThreadCounts.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

constexpr Real kRadius = 0.005;                   // [m]
constexpr Real kLatticeOverlap = 0.005 * kRadius;  // per neighbour [m]
const HertzMaterial kMaterial{1e6, 0.4, 2000, 0.01};

template <class T>
size_t capacityBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

// What the engine keeps per scene beyond the states: neighbour and candidate lists, springs, pairs and records.
size_t engineBytes(const ContactData& data) {
  size_t bytes = capacityBytes(data.neighbours) + capacityBytes(data.neighbourBoxes) + capacityBytes(data.candidateLists) +
                 capacityBytes(data.springs) + capacityBytes(data.boxes) + capacityBytes(data.pairs) +
                 capacityBytes(data.pairResults) + capacityBytes(data.pairRecords) + capacityBytes(data.keptRecords);
  for (const CandidateList& list : data.candidateLists) {
    bytes += capacityBytes(list.pairs) + capacityBytes(list.near);
    if (!list.facet) continue;
    bytes += sizeof(FacetList) + capacityBytes(list.facet->candidates.face);
    for (const std::vector<int>& strip : list.facet->candidates.strips) bytes += capacityBytes(strip);
  }
  return bytes;
}

size_t meshBytes(const RoundedMesh& mesh) {
  const TriangleTree& tree = mesh.tree();
  return capacityBytes(mesh.vertices()) + capacityBytes(mesh.triangles()) +
         mesh.triangleCount() * (sizeof(RoundedTriangle) + sizeof(PrincipalCurvature) + sizeof(AlignedBox3r) + sizeof(int)) +
         capacityBytes(tree.nodes());
}

const RecordedScene& recordedS1() {
  static const RecordedScene loaded = loadRecordedScene();
  return loaded;
}

struct Scene {
  ContactModel model;
  std::vector<BodyState> bodyStates, partnerStates;
  long bodies = 0;
  long primitives = 0;
  size_t meshBytes = 0;
};

// side^3 bodies on the lattice: perfect spheres for subdivisions < 0, else icospheres of that many subdivisions
// (0-3: 12, 42, 162, 642 nodes).
Scene lattice(int side, int subdivisions) {
  Scene scene;
  std::shared_ptr<const RoundedMesh> mesh;
  if (subdivisions >= 0) {
    mesh = std::make_shared<const RoundedMesh>(icosphere(kRadius, subdivisions));
    scene.meshBytes = meshBytes(*mesh);
  }
  std::mt19937 random(1);
  std::normal_distribution<Real> gauss;
  const Real spacing = 2 * kRadius - kLatticeOverlap;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) {
        BodyState state;
        state.position = spacing * Vector3r(i, j, k);
        state.orientation = Quaternionr(gauss(random), gauss(random), gauss(random), gauss(random)).normalized();
        const int id = static_cast<int>(scene.bodies++);
        if (mesh) {
          scene.model.bodies.push_back({id, mesh, kMaterial, kRadius});
          scene.bodyStates.push_back(state);
          scene.primitives += mesh->triangleCount();
        } else {
          scene.model.partners.push_back({id, Sphere{kRadius}, kMaterial, true});
          scene.partnerStates.push_back(state);
          ++scene.primitives;
        }
      }
  return scene;
}

// The recorded S1 packing `tiles` times, on a square of tiles as near as can be, with the floor alone.
Scene tiledS1(int tiles) {
  const RecordedScene& s1 = recordedS1();
  Scene scene;
  AlignedBox3r extent;
  for (const BodyState& state : s1.bodyStates) extent.extend(state.position);
  const Real bound = s1.model.bodies[0].mesh->sphereBoundRadius();
  const Vector3r pitch = extent.sizes().array() + 2 * bound;
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<Real>(tiles))));
  for (int tile = 0; tile < tiles; ++tile) {
    const Vector3r offset(pitch.x() * (tile % columns), pitch.y() * (tile / columns), 0);
    for (size_t b = 0; b < s1.bodyStates.size(); ++b) {
      RoundedBody body = s1.model.bodies[b];
      body.id = static_cast<int>(scene.model.bodies.size());
      scene.model.bodies.push_back(body);
      BodyState state = s1.bodyStates[b];
      state.position += offset;
      scene.bodyStates.push_back(state);
    }
  }
  scene.model.partners = {s1.model.partners[0]};
  scene.model.partners[0].id = static_cast<int>(scene.model.bodies.size());
  scene.partnerStates = {s1.partnerStates[0]};
  scene.bodies = static_cast<long>(scene.model.bodies.size());
  scene.primitives = scene.bodies * s1.model.bodies[0].mesh->triangleCount();
  scene.meshBytes = meshBytes(*s1.model.bodies[0].mesh);
  return scene;
}

void report(benchmark::State& state, const Scene& scene, const ContactData& data, const ContactStatistics& total,
            const StageTimes& times) {
  const auto perStep = benchmark::Counter::kAvgIterations;
  const double bodies = static_cast<double>(scene.bodies);
  state.counters["bodies"] = bodies;
  state.counters["primitives"] = static_cast<double>(scene.primitives);
  state.counters["body_pairs"] = benchmark::Counter(total.bodyPairs, perStep);
  state.counters["contacts"] = benchmark::Counter(total.contacts(), perStep);
  state.counters["broad_ms"] = benchmark::Counter(1e3 * times.broadPhase, perStep);
  state.counters["pairs_ms"] = benchmark::Counter(1e3 * times.pairs, perStep);
  state.counters["ns_per_body_step"] =
      benchmark::Counter(bodies * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["engine_bytes_per_body"] = static_cast<double>(engineBytes(data)) / bodies;
  state.counters["mesh_bytes"] = static_cast<double>(scene.meshBytes);
}

// Every scene is stepped kWarmupSteps times, then timed over kTimedSteps more, the same steps for every size: the
// lists adapt to the motion in the first steps (a new list holds contacts 0.1 r_eq deep), which would otherwise
// weigh more in a large scene, timed over fewer steps.
constexpr int kWarmupSteps = 10;
constexpr int kTimedSteps = 20;

// Steps `scene` as the benchmark asks; `frame(step, data)` may change the states before each step.
template <class Frame>
void run(benchmark::State& state, const Scene& scene, const Frame& frame, int threads = 1) {
  ContactModel model = scene.model;
  model.options.threads = threads;
  ContactData data;
  data.resize(scene.model);
  data.bodyStates = scene.bodyStates;
  data.partnerStates = scene.partnerStates;
  data.timeStep = 1e-4;
  for (int warmup = 0; warmup < 2; ++warmup) contactForces(model, data);
  long step = 0;
  while (step < kWarmupSteps) {
    frame(++step, data);
    contactForces(model, data);
  }
  ContactStatistics total;
  StageTimes times;
  for (auto _ : state) {
    frame(++step, data);
    contactForces(model, data);
    total += data.statistics;
    times.broadPhase += data.times.broadPhase;
    times.pairs += data.times.pairs;
  }
  report(state, scene, data, total, times);
}

// Every body of the lattice moves back and forth along its own direction and turns about its own axis, by up to
// kRattle each way (half the overlap with a neighbour, so that every contact holds), with a period of
// kRattlePeriod steps and its own phase: a packing that rattles, as S1's does at rest.
constexpr Real kRattle = 0.5 * kLatticeOverlap;  // [m]
constexpr int kRattlePeriod = 10;                // steps

void BM_Lattice(benchmark::State& state) {
  const int shape = static_cast<int>(state.range(0));
  const Scene scene = lattice(static_cast<int>(state.range(1)), shape - 1);
  const bool rattling = state.range(2) == 1;
  const bool spheres = scene.model.bodies.empty();
  const std::vector<BodyState>& rest = spheres ? scene.partnerStates : scene.bodyStates;
  std::mt19937 random(2);
  std::normal_distribution<Real> gauss;
  std::uniform_real_distribution<Real> uniform(0, 2 * M_PI);
  std::vector<Vector3r> directions, axes;
  std::vector<Real> phases;
  for (size_t b = 0; b < rest.size(); ++b) {
    directions.push_back(Vector3r(gauss(random), gauss(random), gauss(random)).normalized());
    axes.push_back(Vector3r(gauss(random), gauss(random), gauss(random)).normalized());
    phases.push_back(uniform(random));
  }
  run(state, scene, [&](long step, ContactData& data) {
    if (!rattling) return;
    std::vector<BodyState>& states = spheres ? data.partnerStates : data.bodyStates;
    for (size_t b = 0; b < rest.size(); ++b) {
      const Real s = std::sin(2 * M_PI * step / kRattlePeriod + phases[b]);
      states[b].position = rest[b].position + kRattle * s * directions[b];
      states[b].orientation = Eigen::AngleAxis<Real>(kRattle * s / kRadius, axes[b]) * rest[b].orientation;
    }
  });
  state.SetLabel((shape == 0 ? std::string("spheres") : std::to_string(icosphere(kRadius, shape - 1).vertices().size()) +
                                                              "-node icospheres") +
                 (rattling ? ", rattling" : ", at rest"));
}
BENCHMARK(BM_Lattice)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {6, 8, 10, 13, 16, 20}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(kTimedSteps)
    ->UseRealTime();

void BM_TiledS1(benchmark::State& state) {
  const RecordedScene& s1 = recordedS1();
  const Scene scene = tiledS1(static_cast<int>(state.range(0)));
  const bool shaking = state.range(1) == 1;
  const int threads = static_cast<int>(state.range(2));
  const size_t perTile = s1.bodyStates.size();
  run(state, scene, [&](long step, ContactData& data) {
    if (!shaking) return;
    const std::vector<BodyState>& frame = s1.shaking[frameAt(step, static_cast<int>(s1.shaking.size()))];
    for (size_t b = 0; b < data.bodyStates.size(); ++b) {
      data.bodyStates[b] = frame[b % perTile];
      data.bodyStates[b].position += scene.bodyStates[b].position - s1.bodyStates[b % perTile].position;
    }
    data.partnerStates[0] = frame.back();
  }, threads);
  state.counters["threads"] = threads;
  state.SetLabel(std::string("gummy bears, ") + (shaking ? "shaking" : "settled"));
}
BENCHMARK(BM_TiledS1)
    ->ArgsProduct({{1, 2, 4, 8, 16, 32}, {0, 1}, threadCounts({1})})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(kTimedSteps)
    ->UseRealTime();

}  // namespace
}  // namespace roundedmesh

BENCHMARK_MAIN();
