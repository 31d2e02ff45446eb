// Google Benchmark kernels of the contact pipeline. Run (medians of 10 repetitions, machine in the header):
//   build/bench/roundedmesh_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// doc/benchmarks.md keeps the latest figures.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"
#include "pkg/math/CirclePolygonArea.hpp"
#include "pkg/math/TriangleIntersections.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"

namespace roundedmesh {
namespace {

const HertzMaterial kParticle{1e6, 0.4, 2000, 1e-2, 0};
const HertzMaterial kBox{5e6, 0.4, 2000, 1e-2, 0};

void BM_CirclePolygonArea(benchmark::State& state) {
  const ConvexPolygon triangle = ConvexPolygon::triangle({-0.2, -0.1}, {1.4, 0.3}, {0.2, 1.5});
  for (auto _ : state) benchmark::DoNotOptimize(circlePolygonArea(1.0, triangle));
}
BENCHMARK(BM_CirclePolygonArea);

// S = P ∩ Q and its point closest to the origin for triangle pairs of a contact's size and overlap (two triangles of
// touching surfaces: Q is P turned by up to 30 degrees and moved by up to half its size), one at a time
// (ConvexPolygon) or a batch at a time (TriangleIntersections, the widest vector unit); time per pair.
void BM_TriangleIntersections(benchmark::State& state) {
  constexpr int kPairs = TriangleIntersections::kCapacity;
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> unit(-1, 1);
  std::vector<ConvexPolygon> p(kPairs), q(kPairs);
  for (int k = 0; k < kPairs; ++k) {
    const Vector2r a(unit(rng), unit(rng)), b(unit(rng), unit(rng)), c(unit(rng), unit(rng));
    const Real turn = 0.5 * unit(rng);
    const Matrix2r R = Eigen::Rotation2D<Real>(turn).toRotationMatrix();
    const Vector2r shift(0.5 * unit(rng), 0.5 * unit(rng));
    p[k] = ConvexPolygon::triangle(a, b, c);
    q[k] = ConvexPolygon::triangle(R * a + shift, R * b + shift, R * c + shift);
  }
  const bool batched = state.range(0) == 1;
  TriangleIntersections batch;
  for (auto _ : state) {
    if (batched) {
      batch.size = kPairs;
      for (int k = 0; k < kPairs; ++k) batch.set(k, p[k], q[k]);
      intersectTriangles(batch);
      benchmark::DoNotOptimize(batch.closestX[kPairs - 1]);
    } else {
      for (int k = 0; k < kPairs; ++k) {
        const ConvexPolygon s = p[k].intersection(q[k]);
        benchmark::DoNotOptimize(s.empty() ? Vector2r::Zero().eval() : s.closestPoint(Vector2r::Zero()));
      }
    }
  }
  state.SetItemsProcessed(state.iterations() * kPairs);
  state.SetLabel(batched ? "batched" : "one at a time");
}
BENCHMARK(BM_TriangleIntersections)->Arg(0)->Arg(1);

// One triangle contact through Law2 in each regime (S1 particle on the S1 box, 5 % overlap).
void BM_Law2(benchmark::State& state) {
  const RoundedMesh sphere = icosphere(0.025, 3);
  std::vector<PressureGeom> geoms;
  Ig2_RoundedMesh_Plane_PressureGeom(sphere, Plane{Vector3r(0, 0, -0.025 + 0.00125), Vector3r::UnitZ()},
                                     RelativeMotion(), geoms);
  PressureOptions options;
  options.regime = state.range(0) ? RegimeChoice::Direct : RegimeChoice::Quadrature;
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(kParticle, kBox);
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(Law2_PressureGeom_HertzPhys_IntegratedPressure(geoms[i++ % geoms.size()], phys, options));
  state.SetLabel(state.range(0) ? "direct" : "quadrature");
}
BENCHMARK(BM_Law2)->Arg(0)->Arg(1);

// A whole body-partner contact step: an icosphere of 10 * 4^k + 2 nodes resting on a plane or a box at 5 %
// overlap (broad phase, every triangle's Ig2, Law2, node forces, wrenches).
void BM_SphereContactStep(benchmark::State& state) {
  const int subdivisions = static_cast<int>(state.range(0));
  const bool box = state.range(1);
  const BodyMesh mesh(icosphere(0.025, subdivisions));
  ContactModel model;
  model.bodies.push_back(roundedBody(0, mesh, kParticle));
  if (box)
    model.partners.push_back({1, Box{Vector3r(0.2, 0.2, 0.05)}, kBox});
  else
    model.partners.push_back({1, Plane{Vector3r(0, 0, 0.05), Vector3r::UnitZ()}, kBox});
  ContactData data;
  data.resize(model);
  data.bodyStates[0].position = Vector3r(0.01, 0.02, 0.05 + 0.025 - 0.00125);
  data.bodyStates[0].velocity = Vector3r(0, 0, -0.1);
  for (auto _ : state) {
    contactForces(model, data);
    benchmark::DoNotOptimize(data.bodyWrenches[0].force);
  }
  state.SetLabel(std::to_string(mesh.shape().vertices().size()) + " nodes on a " + (box ? "box" : "plane"));
}
BENCHMARK(BM_SphereContactStep)->ArgsProduct({{2, 3, 4}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace roundedmesh

BENCHMARK_MAIN();
