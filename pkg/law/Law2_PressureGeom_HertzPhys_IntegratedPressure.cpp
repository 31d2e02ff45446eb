#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"

#include <cmath>

#include "pkg/law/FanQuadrature.hpp"
#include "pkg/law/HertzPressure.hpp"
#include "pkg/math/CirclePolygonArea.hpp"
#include "pkg/math/DiskPolygonIntegrals.hpp"
#include "pkg/math/DunavantRule.hpp"

namespace roundedmesh {
namespace {

// r x n12 for r = (x, y) in plane coordinates with t1 x t2 = n12.
Vector2r leverTimesNormal(const Vector2r& r) { return Vector2r(r.y(), -r.x()); }

bool useDirectRegime(const ConvexPolygon& s, Real a, const PressureOptions& options) {
  switch (options.regime) {
    case RegimeChoice::Quadrature:
    case RegimeChoice::Exact: return false;
    case RegimeChoice::Direct: return true;
    case RegimeChoice::Auto: break;
  }
  const int subTriangles = s.size() - 2;
  const Real areaPerPoint = s.area() / (subTriangles * static_cast<Real>(kDunavant8.size()));
  return M_PI * a * a < options.gamma * areaPerPoint;
}

// The integrals below are of the elastic pressure; `damp` then scales the load by Eq. 7's damping.
NormalLoad integrateByQuadrature(const ConvexPolygon& polygon, Real a, const HertzPressure& pressure) {
  // The pressure is zero outside the circle: integrating over S clipped to the circle's square gives the same
  // integral with every quadrature point where the pressure is.
  FanQuadrature points;
  fanQuadrature(polygon.clippedToSquare(a), pressure.contactRadiusSq, points);
  Real integral = 0;
  Vector2r moment = Vector2r::Zero();
  for (int j = 0; j < points.triangles; ++j) {
    using Column = Eigen::Map<const QuadratureColumn, Eigen::Aligned64>;
    const int at = FanQuadrature::kPoints * j;
    const Column x(points.x + at), y(points.y + at), dG(points.dG + at);
    integral += dG.sum();
    moment += leverTimesNormal(Vector2r((dG * x).sum(), (dG * y).sum()));
  }
  return {pressure.amplitude * integral, pressure.amplitude * moment, Regime::Quadrature};
}

NormalLoad applyDirectly(const ConvexPolygon& polygon, Real a, const Vector2r& effectivePoint,
                         const HertzPressure& pressure) {
  const Real fraction = circlePolygonArea(a, polygon) / (M_PI * pressure.contactRadiusSq);
  const Real integral = pressure.circleIntegral() * fraction;
  const Real force = pressure.amplitude * integral;
  return {force, force * leverTimesNormal(effectivePoint), Regime::Direct};
}

// The paper's regimes, chosen by Eq. 14.
NormalLoad integrate(const ConvexPolygon& polygon, const Vector2r& effectivePoint, const HertzPressure& pressure,
                     const PressureOptions& options) {
  const Real a = std::sqrt(pressure.contactRadiusSq);
  return useDirectRegime(polygon, a, options) ? applyDirectly(polygon, a, effectivePoint, pressure)
                                              : integrateByQuadrature(polygon, a, pressure);
}

// An elliptical contact's moment, integrated over T(S), in the plane: on T(S) the moment is (leverTimesNormal of) the
// first moment in y; in the plane x = x* + T^-1 y.
NormalLoad momentInPlane(NormalLoad load, const PressureGeom& geom) {
  if (!geom.elliptical) return load;
  const Vector2r firstMoment(-load.moment.y(), load.moment.x());
  load.moment = leverTimesNormal(load.force * geom.ellipseCentre + geom.toCircle.inverse() * firstMoment);
  return load;
}

}  // namespace

// The closed forms, and the energy with e / (a^2 - r^2)^(3/2) = 4 E* / (3 pi R*^2) [Pa/m^2] (hertzEnergyAmplitude).
NormalLoad exactLoad(const DiskPolygonIntegrals& integrals, const PressureGeom& geom, const HertzPhys& phys) {
  const Real amplitude = hertzElasticAmplitude(phys, geom.radius);
  NormalLoad load{amplitude * integrals.pressure, amplitude * leverTimesNormal(integrals.pressureMoment),
                  Regime::Exact};
  load.elasticEnergy = hertzEnergyAmplitude(phys, geom.radius) * integrals.energy;
  return momentInPlane(load, geom);
}

NormalLoad elasticLoad(const PressureGeom& geom, const HertzPhys& phys, const PressureOptions& options) {
  if (integratesExactly(options))
    return exactLoad(diskPolygonIntegrals(geom.contactRadius, circlePolygon(geom)), geom, phys);
  const HertzPressure pressure{hertzElasticAmplitude(phys, geom.radius), geom.contactRadius * geom.contactRadius};
  NormalLoad load;
  if (geom.elliptical)
    load = integrate(circlePolygon(geom), geom.toCircle * (geom.effectivePoint - geom.ellipseCentre), pressure, options);
  else
    load = integrate(geom.polygon, geom.effectivePoint, pressure, options);
  // A Hertz contact's potential, (2/5) F delta, where the pressure is integrated by the paper's rules.
  load.elasticEnergy = 0.4 * load.force * geom.sphereOverlap;
  return momentInPlane(load, geom);
}

NormalLoad dampedLoad(NormalLoad load, const PressureGeom& geom, const HertzPhys& phys) {
  load.elasticForce = load.force;
  load.elasticMoment = load.moment;
  load.overlapRate = load.force > 0 ? overlapRateAt(geom, centreOfPressure(load)) : geom.overlapRate;
  const Real factor = dampingFactor(phys, geom.sphereOverlap, load.overlapRate);
  load.force *= factor;
  load.moment *= factor;
  return load;
}

NormalLoad Law2_PressureGeom_HertzPhys_IntegratedPressure(const PressureGeom& geom, const HertzPhys& phys,
                                                          const PressureOptions& options) {
  return dampedLoad(elasticLoad(geom, phys, options), geom, phys);
}

}  // namespace roundedmesh
