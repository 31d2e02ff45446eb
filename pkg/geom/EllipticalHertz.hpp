// Hertz's elliptical contact (Johnson, Contact Mechanics, Cambridge University Press 1985, Section 4.2): two
// surfaces whose gap is (lambdaA x^2 + lambdaB y^2) / 2 near the first touch, lambdaA <= lambdaB the relative
// principal curvatures [1/m] (for two spheres both are 1/R*, Eq. 3), pressed together by delta [m], touch on the
// ellipse of semi-axes a along x, b <= a along y, under the pressure
//   p(x, y) = p0 sqrt(1 - x^2/a^2 - y^2/b^2),  force (2 pi / 3) a b p0,
// with the eccentricity e (b^2 = a^2 (1 - e^2)) given by the ratio of the curvatures and complete elliptic
// integrals K(e), E(e):
//   lambdaB / lambdaA = (E / (1 - e^2) - K) / (K - E),
//   a^2 = 2 delta (K - E) / (K e^2 lambdaA),  p0 = E* delta / (b K).
// For lambdaA = lambdaB it is the circle of the paper, a^2 = delta R* (Eq. 5) and p0 = 2 E* a / (pi R*) (Eq. 9).
// Line contact: a direction whose curvature is below 1/kLineContactRatio of the other's is flat (parallel
// cylinders); then the pressure is the two-dimensional Hertz solution across it, uniform along it,
//   p(y) = p0 sqrt(1 - y^2/b^2),  b^2 = delta / lambdaB,  p0 = E* delta / (2 b),
// whose force per unit length (pi/4) E* delta is the paper's Eq. 27; it is represented as an ellipse with
// a = kLineLength b, whose pressure differs from the strip's by (x/a)^2 / 2 over the triangle pair. Between the
// ratios kEllipseLimit and kLineContactRatio, a, b and p0 pass from Hertz's ellipse to the line contact
// geometrically in ln(ratio): Hertz's ellipse there is 20 to 80 times longer than wide, and its force, which
// falls as 1/K(e) ~ 1/ln(a/b) for infinite bodies, no longer describes bodies of finite length; the blend keeps
// the force continuous as two cylinders turn parallel. Mesh noise (tilted triangles) leaves ratios of 10^3 to
// 10^5 on parallel cylinders: line contacts.
// The eccentricity comes from a table over ln(lambdaB / lambdaA) built once from std::comp_ellint_1/2 (2048
// intervals up to kLineContactRatio; linear interpolation, relative error below 1e-5, tested against Hertz's equations
// solved independently in EllipticalContactTest).
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

constexpr Real kEllipseLimit = 1e2;
constexpr Real kLineContactRatio = 1e3;
constexpr Real kLineLength = 1e4;

struct HertzEllipse {
  Real a, b;         // semi-axes [m], a along the direction of lambdaA
  Real peakPerModulus;  // p0 / E* [1]
};

// lambdaB > 0, lambdaA <= lambdaB (a lambdaA below lambdaB / kLineContactRatio, even negative, is a line
// contact), delta > 0.
HertzEllipse hertzEllipse(Real lambdaA, Real lambdaB, Real delta);

}  // namespace roundedmesh
