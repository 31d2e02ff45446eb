// Google Benchmark of the complete C++ contact step on scene S1 with 250 gummy bears (bench/data, recorded
// by scripts/benchmarks/record_s1_scene.py), without YADE or Python, and of its two per-contact stages:
//   BM_S1Step/threads/motion/skin/steps/near/friction/curvature   one contactForces step (stages 2-4 of ContactStep.hpp); motion = 0: the settled
//                              packing again and again (the lists kept between steps stay valid), 1: the recorded
//                              steps of shaking in order, forth and back (the lists are rebuilt as the bodies move),
//                              2: the recorded steps of the packing resting in the standing box (it rattles),
//                              3: the recorded steps of a whole run's landing window (t = 0.45 s on);
//                              friction = 0: S1's frictionless materials, 1: mu = 0.5 and c = 10 N s/m on every
//                              material with the tangential spring, 2: the same with the paper's viscous law;
//                              curvature = 0: the paper's circle (mean curvature), 1: the ellipse of both principal
//                              curvatures (estimated from the recorded mesh)
//   s1Step/without_core/...    the same without the deep-overlap core (core_inset = 1): what the core costs
//   s1Step/energy_law/...      the same under normal = 'energy', the same poses and lists: the two laws' step
//   s1Step/stages/...          the same with timing = 'stages': the CPU time of each stage inside the pairs (lists,
//                              near searches, narrow phase, law, core) per step, and the near pairs scanned
//   BM_S1NarrowPhase           Ig2 over every pair's candidates of the settled packing (time per contact)
//   BM_S1NarrowPhaseLanes/lanes  Ig2 over every pair of two bears' candidates of the settled packing, one candidate
//                              at a time (0) or in lanes (1) on the vector unit in use (time per contact)
//   BM_S1Load/friction         Law2, node forces and friction over its triangle contacts (time per contact)
//   BM_S1NarrowPhaseThenLoad   Ig2 and then Law2 (friction 0) for each pair in turn, as the step runs them: the two
//                              stages' time per contact in place, the law's records still in cache
//   BM_S1NearSearch/motion     the near searches in the triangle trees of every body pair's list, the settled
//                              packing (0) or a step of the landing window (3) (time per search)
// Counters per step: body pairs, candidates, contacts, candidates per contact, list rebuilds, stage times.
//   build/bench/roundedmesh_s1_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The thread counts of the first BM_S1Step series are 1 and 2, or those listed in ROUNDEDMESH_BENCH_THREADS
// (comma-separated, for larger machines), e.g. ROUNDEDMESH_BENCH_THREADS=1,2,4,8,16. The kernels run on the
// processor's best vector unit, or the one named in ROUNDEDMESH_BENCH_TARGET, e.g. ROUNDEDMESH_BENCH_TARGET=SSE4.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/InstructionSet.hpp"
#include "bench/RecordedScene.hpp"
#include "bench/ThreadCounts.hpp"
#include "pkg/bound/BatchedCandidates.hpp"
#include "pkg/bound/TrianglePairCandidates.hpp"
#include "pkg/engine/CandidateLists.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {
namespace {

const RecordedScene& scene() {
  static const RecordedScene loaded = loadRecordedScene();
  return loaded;
}

// S1's model, with friction on every material for friction = 1 (the spring) or 2 (the viscous law).
ContactModel withFriction(ContactModel model, long friction) {
  if (friction == 0) return model;
  model.options.friction = friction == 1 ? FrictionLaw::Spring : FrictionLaw::Viscous;
  for (RoundedBody& body : model.bodies) {
    body.material.friction = 0.5;
    body.material.tangentialDamping = 10;
  }
  for (Partner& partner : model.partners) {
    partner.material.friction = 0.5;
    partner.material.tangentialDamping = 10;
  }
  return model;
}

// One step of S1's contacts; `core`: with the deep-overlap core (the default), or without it (core_inset = 1);
// `stages`: timing = 'stages'; `normal`: the normal law.
void s1Step(benchmark::State& state, bool core, bool stages, NormalLaw normal = NormalLaw::Pressure) {
  const int threads = static_cast<int>(state.range(0));
  const int motion = static_cast<int>(state.range(1));
  const RecordedScene::Trajectory* trajectory = motion == 1   ? &scene().shaking
                                                : motion == 2 ? &scene().resting
                                                : motion == 3 ? &scene().landing
                                                              : nullptr;
  ContactModel model = withFriction(scene().model, state.range(5));
  model.options.threads = threads;
  if (state.range(2) > 0) model.skins.candidatesMin = model.skins.candidatesMax = 1e-4 * state.range(2);
  if (state.range(3) > 0) model.skins.candidateSteps = static_cast<Real>(state.range(3));
  if (state.range(4) > 0) model.skins.nearFactor = static_cast<Real>(state.range(4));
  if (state.range(6) == 1) model.options.pressure.curvature = CurvatureModel::Principal;
  if (!core) model.options.coreInset = 1;
  if (stages) model.options.timing = Timing::Stages;
  model.options.pressure.normal = normal;
  ContactData data;
  data.timeStep = 1e-4;  // S1's
  if (trajectory)
    scene().setStates(data, *trajectory, 0);
  else
    scene().setStates(data);
  for (int warmup = 0; warmup < 2; ++warmup) contactForces(model, data);  // builds and trims the lists
  ContactStatistics total;
  StageTimes times;
  long steps = 0;
  for (auto _ : state) {
    if (trajectory) scene().setStates(data, *trajectory, frameAt(++steps, static_cast<int>(trajectory->size())));
    contactForces(model, data);
    total += data.statistics;
    times.broadPhase += data.times.broadPhase;
    times.pairs += data.times.pairs;
    times.reduction += data.times.reduction;
  }
  const auto perStep = benchmark::Counter::kAvgIterations;
  state.counters["body_pairs"] = benchmark::Counter(total.bodyPairs, perStep);
  state.counters["touching_pairs"] = benchmark::Counter(total.touchingPairs, perStep);
  state.counters["candidates"] = benchmark::Counter(total.narrowPhase.candidates, perStep);
  state.counters["not_facing"] = benchmark::Counter(total.narrowPhase.notFacing, perStep);
  state.counters["no_overlap"] = benchmark::Counter(total.narrowPhase.noOverlap, perStep);
  state.counters["outside_circle"] = benchmark::Counter(total.narrowPhase.outsideCircle, perStep);
  state.counters["empty_polygon"] = benchmark::Counter(total.narrowPhase.emptyPolygon, perStep);
  state.counters["beyond_contact_circle"] = benchmark::Counter(total.narrowPhase.beyondContactCircle, perStep);
  state.counters["through_body"] = benchmark::Counter(total.narrowPhase.throughBody, perStep);
  state.counters["contacts"] = benchmark::Counter(total.contacts(), perStep);
  state.counters["candidates_per_contact"] = static_cast<double>(total.narrowPhase.candidates) / total.contacts();
  state.counters["list_rebuilds"] = benchmark::Counter(total.candidateRebuilds, perStep);
  state.counters["near_rebuilds"] = benchmark::Counter(total.nearRebuilds, perStep);
  state.counters["neighbour_rebuilds"] = benchmark::Counter(total.neighbourRebuilds, perStep);
  state.counters["broad_ms"] = benchmark::Counter(1e3 * times.broadPhase, perStep);
  state.counters["pairs_ms"] = benchmark::Counter(1e3 * times.pairs, perStep);
  state.counters["reduction_ms"] = benchmark::Counter(1e3 * times.reduction, perStep);
  if (stages) {
    state.counters["near_pairs_scanned"] = benchmark::Counter(static_cast<double>(total.nearPairsScanned), perStep);
    state.counters["lists_cpu_ms"] = benchmark::Counter(1e3 * total.cpu.lists, perStep);
    state.counters["near_search_cpu_ms"] = benchmark::Counter(1e3 * total.cpu.nearSearch, perStep);
    state.counters["narrow_phase_cpu_ms"] = benchmark::Counter(1e3 * total.cpu.narrowPhase, perStep);
    state.counters["law_cpu_ms"] = benchmark::Counter(1e3 * total.cpu.law, perStep);
    state.counters["core_cpu_ms"] = benchmark::Counter(1e3 * total.cpu.core, perStep);
  }
  state.SetLabel(std::string(motion == 1 ? "shaking" : motion == 2 ? "resting" : motion == 3 ? "landing" : "settled") + ", " +
                 std::to_string(threads) + " thread(s)" +
                 (state.range(5) == 1 ? ", spring" : state.range(5) == 2 ? ", viscous" : "") +
                 (state.range(6) == 1 ? ", principal curvatures" : "") + (core ? "" : ", without the core") +
                 (normal == NormalLaw::Energy ? ", energy law" : "") +
                 ", batches on " + batchedTarget());
}

void BM_S1Step(benchmark::State& state) { s1Step(state, true, false); }
BENCHMARK(BM_S1Step)->ArgsProduct({threadCounts({1, 2}), {0, 1, 2, 3}, {0}, {0}, {0}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
// The energy law's step on the same poses and lists as BM_S1Step's (issue 41: its cost beside the paper's law).
BENCHMARK_CAPTURE(s1Step, energy_law, true, false, NormalLaw::Energy)->ArgsProduct({threadCounts({1, 2}), {0, 1, 2}, {0}, {0}, {0}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
// Where the time of a step goes, stage by stage.
BENCHMARK_CAPTURE(s1Step, stages, true, true)->ArgsProduct({threadCounts({1, 2}), {0, 1, 2, 3}, {0}, {0}, {0}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
// What the deep-overlap core costs: the same steps without it.
BENCHMARK_CAPTURE(s1Step, without_core, false, false)->ArgsProduct({threadCounts({1, 2}), {0, 1, 2}, {0}, {0}, {0}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
// With friction: the spring and the viscous law.
BENCHMARK(BM_S1Step)->ArgsProduct({{1}, {0, 1}, {0}, {0}, {0}, {1, 2}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
// The ellipse of both principal curvatures (issue 13), settled and resting, frictionless and with the spring.
BENCHMARK(BM_S1Step)->ArgsProduct({{1}, {0, 2}, {0}, {0}, {0}, {0, 1}, {1}})->Unit(benchmark::kMillisecond)->UseRealTime();
// The lists' parameters (0: the model's default): a fixed skin in 1e-4 of the smaller volume-equivalent
// radius, instead of one that follows each pair's motion; the steps a list is meant to last; the near list's
// skin as a multiple of the candidates'.
BENCHMARK(BM_S1Step)->ArgsProduct({{1}, {0, 1}, {20, 80}, {0}, {0}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_S1Step)->ArgsProduct({{1}, {1, 2}, {0}, {5, 20, 40}, {3, 5, 10}, {0}, {0}})->Unit(benchmark::kMillisecond)->UseRealTime();

// The counters of a benchmark timed per triangle contact: ns_per_contact, the time of one iteration over `contacts`.
void countPerContact(benchmark::State& state, long contacts) {
  state.counters["ns_per_contact"] = benchmark::Counter(
      static_cast<double>(contacts) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["contacts"] = static_cast<double>(contacts);
}

// The settled packing after one step: its pairs with their candidate lists, and every pair's contacts.
struct SettledStep {
  ContactData data;
  std::vector<std::vector<PressureGeom>> geoms;  // per pair
  long contacts = 0;

  SettledStep() {
    scene().setStates(data);
    contactForces(scene().model, data);
    for (const BodyPair& pair : data.pairs) {
      ContactStatistics statistics;
      pairGeometry(scene().model, data, pair, geoms.emplace_back(), statistics, &data.candidateLists[pair.neighbour]);
      contacts += static_cast<long>(geoms.back().size());
    }
    data.timeStep = 1e-4;  // S1's, for the law's springs in the benchmarks that load these contacts
  }
};

SettledStep& settled() {
  static SettledStep step;
  return step;
}

void BM_S1NarrowPhase(benchmark::State& state) {
  SettledStep& step = settled();
  std::vector<PressureGeom> geoms;
  for (auto _ : state)
    for (const BodyPair& pair : step.data.pairs) {
      ContactStatistics statistics;
      pairGeometry(scene().model, step.data, pair, geoms, statistics, &step.data.candidateLists[pair.neighbour]);
      benchmark::DoNotOptimize(geoms.data());
    }
  countPerContact(state, step.contacts);
}
BENCHMARK(BM_S1NarrowPhase)->Unit(benchmark::kMillisecond);

// What PolygonLanes chooses between, on the same candidates (triangleIntersectionsPay() decides it in the engine).
void BM_S1NarrowPhaseLanes(benchmark::State& state) {
  const ContactModel& model = scene().model;
  SettledStep& step = settled();
  const PolygonLanes lanes = state.range(0) == 1 ? PolygonLanes::Always : PolygonLanes::Never;
  std::vector<const BodyPair*> bodyPairs;
  std::vector<BodyPairFrame> frames;
  for (const BodyPair& pair : step.data.pairs)
    if (pair.other < static_cast<int>(model.bodies.size())) {
      bodyPairs.push_back(&pair);
      frames.push_back(bodyPairFrame(model, step.data, pair));
    }
  std::vector<PressureGeom> geoms;
  long contacts = 0;
  for (auto _ : state) {
    contacts = 0;
    for (size_t k = 0; k < bodyPairs.size(); ++k) {
      const BodyPair& pair = *bodyPairs[k];
      const BodyPairFrame& frame = frames[k];
      geoms.clear();
      Ig2_RoundedMesh_RoundedMesh_PressureGeom(*model.bodies[pair.body].mesh, *model.bodies[pair.other].mesh,
                                               frame.rotation, frame.translation,
                                               step.data.candidateLists[pair.neighbour].pairs, frame.shallow,
                                               frame.motion, GeomOutput(geoms), CurvatureModel::Mean, lanes);
      contacts += static_cast<long>(geoms.size());
    }
  }
  countPerContact(state, contacts);
  state.SetLabel(std::string(lanes == PolygonLanes::Always ? "in lanes on " : "one at a time; vector unit ") +
                 batchedTarget());
}
BENCHMARK(BM_S1NarrowPhaseLanes)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Law2 and the normal law for every pair of the settled step: frictionless, with the spring or the viscous law
// (the argument).
void s1Load(benchmark::State& state, NormalLaw normal) {
  SettledStep& step = settled();
  ContactModel model = withFriction(scene().model, state.range(0));
  model.options.pressure.normal = normal;
  for (auto _ : state)
    for (size_t k = 0; k < step.data.pairs.size(); ++k)
      benchmark::DoNotOptimize(pairLoad(model, step.data, step.data.pairs[k], step.geoms[k], nullptr,
                                        &step.data.springs[step.data.pairs[k].neighbour]));
  countPerContact(state, step.contacts);
}
void BM_S1Load(benchmark::State& state) { s1Load(state, NormalLaw::Pressure); }
BENCHMARK(BM_S1Load)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
// The energy law (rm.engine(normal='energy')), frictionless.
void BM_S1EnergyLoad(benchmark::State& state) { s1Load(state, NormalLaw::Energy); }
BENCHMARK(BM_S1EnergyLoad)->Arg(0)->Unit(benchmark::kMillisecond);

// Ig2 and then Law2 for each pair in turn, as the step runs them (ContactStep.cpp): the law reads a pair's contact
// records while the narrow phase's writes are still in cache, where BM_S1Load reads every pair's from memory.
void BM_S1NarrowPhaseThenLoad(benchmark::State& state) {
  SettledStep& step = settled();
  const ContactModel& model = scene().model;
  std::vector<PressureGeom> geoms;
  for (auto _ : state)
    for (const BodyPair& pair : step.data.pairs) {
      ContactStatistics statistics;
      pairGeometry(model, step.data, pair, geoms, statistics, &step.data.candidateLists[pair.neighbour]);
      benchmark::DoNotOptimize(pairLoad(model, step.data, pair, geoms, nullptr, &step.data.springs[pair.neighbour]));
    }
  countPerContact(state, step.contacts);
}
BENCHMARK(BM_S1NarrowPhaseThenLoad)->Unit(benchmark::kMillisecond);

// The near searches (nearTrianglePairs) of every body pair's list after one step of the settled packing (0) or of
// the landing window's step 10 (3), each at the pose, skin and depth its near list was built with.
void BM_S1NearSearch(benchmark::State& state) {
  const ContactModel& model = scene().model;
  ContactData data;
  if (state.range(0) == 0)
    scene().setStates(data);
  else
    scene().setStates(data, scene().landing, 10);
  contactForces(model, data);
  const int bodyCount = static_cast<int>(model.bodies.size());
  std::vector<size_t> searched;
  long nearPairs = 0;
  for (size_t n = 0; n < data.neighbours.size(); ++n)
    if (data.candidateLists[n].nearSkin > 0 && data.neighbours[n].other < bodyCount) {
      searched.push_back(n);
      nearPairs += static_cast<long>(data.candidateLists[n].near.size());
    }
  std::vector<TrianglePair> near;
  for (auto _ : state)
    for (const size_t n : searched) {
      const BodyPair& pair = data.neighbours[n];
      const CandidateList& list = data.candidateLists[n];
      const RoundedBody &body = model.bodies[pair.body], &other = model.bodies[pair.other];
      const Real shallow = kDeepestOverlap * std::min(body.equivalentRadius, other.equivalentRadius);
      nearTrianglePairs(*body.mesh, *other.mesh, list.nearRotation.toRotationMatrix(), list.nearTranslation,
                        list.nearSkin, list.nearDepth, shallow, near);
      benchmark::DoNotOptimize(near.data());
    }
  state.counters["us_per_search"] =
      benchmark::Counter(static_cast<double>(searched.size()) * 1e-6,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["searches"] = static_cast<double>(searched.size());
  state.counters["near_pairs"] = static_cast<double>(nearPairs);
}
BENCHMARK(BM_S1NearSearch)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roundedmesh

int main(int argc, char** argv) {
  roundedmesh::chooseInstructionSet();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
