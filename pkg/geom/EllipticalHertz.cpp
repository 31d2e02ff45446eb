#include "pkg/geom/EllipticalHertz.hpp"

#include <array>
#include <cmath>

namespace roundedmesh {
namespace {

constexpr int kIntervals = 2048;

// Over s = ln(lambdaB / lambdaA) in [0, ln kLineContactRatio]: (K - E) / (K e^2), 1 - e^2 and K.
struct EllipseTable {
  Real step;
  std::array<Real, kIntervals + 1> axis, squeeze, integral;

  EllipseTable() : step(std::log(kLineContactRatio) / kIntervals) {
    axis[0] = 0.5;
    squeeze[0] = 1;
    integral[0] = M_PI / 2;
    for (int i = 1; i <= kIntervals; ++i) {
      const Real ratio = std::exp(i * step);
      // ratio grows with e; bisection on w = -ln(1 - e^2), which spreads the eccentricities near 1.
      Real low = 0, high = 60;
      for (int iteration = 0; iteration < 200 && high - low > 1e-15 * high; ++iteration) {
        const Real w = 0.5 * (low + high);
        const Real m = -std::expm1(-w), k = std::sqrt(m);
        const Real K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
        ((E / std::exp(-w) - K) / (K - E) < ratio ? low : high) = w;
      }
      const Real m = -std::expm1(-0.5 * (low + high)), k = std::sqrt(m);
      const Real K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
      axis[i] = (K - E) / (K * m);
      squeeze[i] = 1 - m;
      integral[i] = K;
    }
  }
};

const EllipseTable& table() {
  static const EllipseTable t;
  return t;
}

}  // namespace

HertzEllipse hertzEllipse(Real lambdaA, Real lambdaB, Real delta) {
  const Real lineWidth = std::sqrt(delta / lambdaB);
  const HertzEllipse line{kLineLength * lineWidth, lineWidth, delta / (2 * lineWidth)};
  if (!(lambdaA * kLineContactRatio > lambdaB)) return line;
  const EllipseTable& t = table();
  const Real s = std::log(lambdaB / lambdaA);
  const Real position = s / t.step;
  const int i = std::min(static_cast<int>(position), kIntervals - 1);
  const Real w = position - i;
  auto at = [&](const std::array<Real, kIntervals + 1>& column) { return (1 - w) * column[i] + w * column[i + 1]; };
  const Real a = std::sqrt(2 * delta * at(t.axis) / lambdaA);
  const Real b = a * std::sqrt(at(t.squeeze));
  const HertzEllipse hertz{a, b, delta / (b * at(t.integral))};
  const Real toLine = (s - std::log(kEllipseLimit)) / std::log(kLineContactRatio / kEllipseLimit);
  if (!(toLine > 0)) return hertz;
  auto blend = [&](Real x, Real y) { return std::pow(x, 1 - toLine) * std::pow(y, toLine); };
  return {blend(hertz.a, line.a), blend(hertz.b, line.b), blend(hertz.peakPerModulus, line.peakPerModulus)};
}

}  // namespace roundedmesh
