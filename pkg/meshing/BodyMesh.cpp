#include "pkg/meshing/BodyMesh.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pkg/meshing/MeshPreparation.hpp"
#include "pkg/shape/CapTolerance.hpp"
#include "pkg/shape/Curvature.hpp"
#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

MassProperties solidMassProperties(const std::vector<Vector3r>& vertices, const std::vector<Triangle>& triangles) {
  requireValidSurface({vertices, triangles});
  return massProperties(vertices, triangles);
}

std::vector<Real> inverse(const std::vector<Real>& values) {
  std::vector<Real> out;
  out.reserve(values.size());
  for (Real v : values) out.push_back(1 / v);
  return out;
}

}  // namespace

Real defaultMaxRadius(Real volume) { return 100 * equivalentRadius(volume); }

BodyMesh::BodyMesh(const TriangleSurface& input, const std::optional<std::vector<Real>>& prescribedCurvatures,
                   std::optional<Real> maxRadius, std::optional<std::vector<PrincipalCurvature>> prescribedPrincipal,
                   std::optional<CapPolicy> caps) {
  MassProperties mass = solidMassProperties(input.vertices, input.triangles);
  if (prescribedCurvatures && prescribedCurvatures->size() != input.triangles.size())
    throw std::invalid_argument("curvature: " + std::to_string(prescribedCurvatures->size()) + " values given for " +
                                std::to_string(input.triangles.size()) + " triangles");
  curvature_.source = prescribedCurvatures ? CurvatureSource::Prescribed : CurvatureSource::Computed;
  curvature_.maxRadius = maxRadius.value_or(defaultMaxRadius(mass.volume));
  const bool bounded = caps && curvature_.source == CurvatureSource::Computed;
  if (caps && !(caps->tolerance > 0))
    throw std::invalid_argument("tolerance: must be positive, got " + std::to_string(caps->tolerance));
  const Real maxCapHeight = bounded ? caps->tolerance * equivalentRadius(mass.volume) : 0;
  TriangleSurface surface = input;
  if (bounded && caps->remesh) {
    PreparedSurface prepared = surfaceWithinTolerance(input, curvature_.maxRadius, maxCapHeight);
    remeshPasses_ = prepared.remeshPasses;
    remeshEdgeLength_ = prepared.edgeLength;
    if (remeshPasses_ > 0) {
      surface = std::move(prepared.surface);
      mass = solidMassProperties(surface.vertices, surface.triangles);
    }
  }
  curvature_.meanCurvatures = prescribedCurvatures ? *prescribedCurvatures : meanCurvature(surface).triangles;
  std::vector<PrincipalCurvature> principal;
  if (prescribedPrincipal) {
    principal = std::move(*prescribedPrincipal);
  } else if (prescribedCurvatures) {
    for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t)
      principal.push_back(PrincipalCurvature::isotropic((*prescribedCurvatures)[t], triangleNormal(surface, t)));
  } else {
    principal = principalCurvatures(surface);
  }
  std::vector<Real> radii = contactRadii(curvature_.meanCurvatures, curvature_.maxRadius);
  if (bounded) boundedCaps_ = boundCapHeights(surface, maxCapHeight, radii, principal);
  placeInPrincipalFrame(RoundedMesh(surface.vertices, surface.triangles, std::move(radii), std::move(principal)),
                        mass);
}

BodyMesh::BodyMesh(const RoundedMesh& inputFrameMesh) {
  const MassProperties mass = solidMassProperties(inputFrameMesh.vertices(), inputFrameMesh.triangles());
  curvature_ = {inverse(inputFrameMesh.radii()), CurvatureSource::Prescribed, defaultMaxRadius(mass.volume)};
  placeInPrincipalFrame(inputFrameMesh, mass);
}

void BodyMesh::placeInPrincipalFrame(const RoundedMesh& inputFrameMesh, const MassProperties& mass) {
  const PrincipalAxes axes = principalAxes(mass.inertia);
  volume_ = mass.volume;
  principalMoments_ = axes.moments;
  inputCentroid_ = mass.centroid;
  inputOrientation_ = axes.orientation;
  const Matrix3r toBody = axes.orientation.conjugate().toRotationMatrix();
  shape_ = std::make_shared<const RoundedMesh>(inputFrameMesh.transformed(toBody, -toBody * mass.centroid));
}

BodyMesh::BodyMesh(const RoundedMesh& bodyFrameMesh, const Vector3r& inputCentroid,
                   const Quaternionr& inputOrientation, SurfaceCurvature curvature)
    : shape_(std::make_shared<const RoundedMesh>(bodyFrameMesh)),
      curvature_(std::move(curvature)),
      inputCentroid_(inputCentroid),
      inputOrientation_(inputOrientation.normalized()) {
  const MassProperties mass = solidMassProperties(bodyFrameMesh.vertices(), bodyFrameMesh.triangles());
  if (curvature_.meanCurvatures.size() != bodyFrameMesh.radii().size())
    throw std::invalid_argument("curvature: one value per triangle expected");
  const Real size = boundingBox(bodyFrameMesh.vertices()).diagonal().norm();
  const Matrix3r offDiagonal = mass.inertia - Matrix3r(mass.inertia.diagonal().asDiagonal());
  if (mass.centroid.norm() > 1e-6 * size || offDiagonal.norm() > 1e-6 * mass.inertia.trace())
    throw std::invalid_argument("mesh: the vertices are not in the principal frame of the mesh");
  volume_ = mass.volume;
  principalMoments_ = mass.inertia.diagonal();
}

TriangleSurface BodyMesh::inputFrameSurface() const {
  TriangleSurface s{shape_->vertices(), shape_->triangles()};
  const Matrix3r rotation = inputOrientation_.toRotationMatrix();
  for (Vector3r& v : s.vertices) v = rotation * v + inputCentroid_;
  return s;
}

}  // namespace roundedmesh
