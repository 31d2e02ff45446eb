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

// The pressure's shape sqrt(a^2 - r^2) is integrated once; the amplitudes, damped and elastic, scale it.
NormalLoad integrateByQuadrature(const ConvexPolygon& polygon, const HertzPressure& pressure) {
  // The pressure is zero outside the circle: integrating over S clipped to the circle's square gives the same
  // integral with every quadrature point where the pressure is.
  FanQuadrature points;
  fanQuadrature(polygon.clippedToSquare(std::sqrt(pressure.contactRadiusSq)), pressure.contactRadiusSq, points);
  Real integral = 0;
  Vector2r moment = Vector2r::Zero();
  for (int j = 0; j < points.triangles; ++j) {
    using Column = Eigen::Map<const QuadratureColumn, Eigen::Aligned64>;
    const int at = FanQuadrature::kPoints * j;
    const Column x(points.x + at), y(points.y + at), dG(points.dG + at);
    integral += dG.sum();
    moment += leverTimesNormal(Vector2r((dG * x).sum(), (dG * y).sum()));
  }
  return {pressure.amplitude * integral, pressure.amplitude * moment, Regime::Quadrature,
          pressure.elasticAmplitude * integral, pressure.elasticAmplitude * moment};
}

NormalLoad applyDirectly(const ConvexPolygon& polygon, const Vector2r& effectivePoint, const HertzPressure& pressure) {
  const Real fraction = circlePolygonArea(std::sqrt(pressure.contactRadiusSq), polygon) / (M_PI * pressure.contactRadiusSq);
  const Real integral = pressure.circleIntegral() * fraction;
  const Real force = pressure.amplitude * integral;
  const Real elastic = pressure.elasticAmplitude * integral;
  return {force, force * leverTimesNormal(effectivePoint), Regime::Direct, elastic,
          elastic * leverTimesNormal(effectivePoint)};
}

// The closed forms; `energyAmplitude`: e / (a^2 - r^2)^(3/2) = (4 E* / (3 pi R*^2)) [Pa/m^2].
NormalLoad integrateExactly(const ConvexPolygon& polygon, const HertzPressure& pressure, Real energyAmplitude) {
  const DiskPolygonIntegrals integrals = diskPolygonIntegrals(std::sqrt(pressure.contactRadiusSq), polygon);
  const Vector2r moment = leverTimesNormal(integrals.pressureMoment);
  NormalLoad load{pressure.amplitude * integrals.pressure, pressure.amplitude * moment, Regime::Exact,
                  pressure.elasticAmplitude * integrals.pressure, pressure.elasticAmplitude * moment};
  load.elasticEnergy = energyAmplitude * integrals.energy;
  return load;
}

NormalLoad integrate(const ConvexPolygon& polygon, const Vector2r& effectivePoint, const HertzPressure& pressure,
                     const PressureOptions& options, Real energyAmplitude) {
  if (options.regime == RegimeChoice::Exact || options.normal == NormalLaw::Energy)
    return integrateExactly(polygon, pressure, energyAmplitude);
  return useDirectRegime(polygon, std::sqrt(pressure.contactRadiusSq), options)
             ? applyDirectly(polygon, effectivePoint, pressure)
             : integrateByQuadrature(polygon, pressure);
}

}  // namespace

NormalLoad Law2_PressureGeom_HertzPhys_IntegratedPressure(const PressureGeom& geom, const HertzPhys& phys,
                                                          const PressureOptions& options) {
  const HertzPressure pressure = hertzPressure(geom, phys);
  const Real energyAmplitude = hertzEnergyAmplitude(phys, geom.radius);
  NormalLoad load =
      geom.elliptical
          ? integrate(circlePolygon(geom), geom.toCircle * (geom.effectivePoint - geom.ellipseCentre), pressure,
                      options, energyAmplitude)
          : integrate(geom.polygon, geom.effectivePoint, pressure, options, energyAmplitude);
  // A Hertz contact's potential, (2/5) F delta, where the pressure is integrated by the paper's rules.
  if (load.regime != Regime::Exact) load.elasticEnergy = 0.4 * load.elasticForce * geom.sphereOverlap;
  if (geom.elliptical) {
    // On T(S) the moment is (leverTimesNormal of) the first moment in y; in the plane x = x* + T^-1 y.
    auto toPlane = [&](Real force, const Vector2r& moment) {
      const Vector2r firstMoment(-moment.y(), moment.x());
      return leverTimesNormal(force * geom.ellipseCentre + geom.toCircle.inverse() * firstMoment);
    };
    load.moment = toPlane(load.force, load.moment);
    load.elasticMoment = toPlane(load.elasticForce, load.elasticMoment);
  }
  return load;
}

}  // namespace roundedmesh
