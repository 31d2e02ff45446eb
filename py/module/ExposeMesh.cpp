// roundedmesh.Mesh: a closed rounded mesh in its principal frame (pkg/shape/BodyMesh.hpp).
#include <boost/python.hpp>
#include <memory>
#include <sstream>

#include "pkg/shape/BodyMesh.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "py/module/NumpyConversion.hpp"

namespace roundedmesh::python {
namespace {

std::shared_ptr<BodyMesh> makeMesh(const bp::object& vertices, const bp::object& triangles, const bp::object& radius) {
  std::vector<Triangle> corners = toTriangles(triangles, "triangles");
  const std::vector<Real> radii = toPerTriangle(radius, static_cast<int>(corners.size()), "radius");
  return std::make_shared<BodyMesh>(RoundedMesh(toPoints(vertices, "vertices"), std::move(corners), radii));
}

std::shared_ptr<BodyMesh> makeIcosphere(Real radius, int subdivisions) {
  return std::make_shared<BodyMesh>(icosphere(radius, subdivisions));
}

std::vector<Vector3r> perTriangle(const BodyMesh& mesh, Vector3r RoundedTriangle::*field) {
  std::vector<Vector3r> out(mesh.shape().triangleCount());
  for (int t = 0; t < mesh.shape().triangleCount(); ++t) out[t] = mesh.shape().rounded(t).*field;
  return out;
}

std::vector<Real> areas(const BodyMesh& mesh) {
  std::vector<Real> out(mesh.shape().triangleCount());
  for (int t = 0; t < mesh.shape().triangleCount(); ++t) out[t] = mesh.shape().rounded(t).area;
  return out;
}

np::ndarray centroid(const BodyMesh& m) { return toArray(std::vector<Real>(m.inputCentroid().data(), m.inputCentroid().data() + 3)); }
np::ndarray inertia(const BodyMesh& m) { return toArray(std::vector<Real>(m.principalMoments().data(), m.principalMoments().data() + 3)); }

std::string repr(const BodyMesh& m) {
  std::ostringstream s;
  s << "<roundedmesh.Mesh: " << m.shape().vertices().size() << " vertices, " << m.shape().triangleCount()
    << " triangles, volume " << m.volume() << " m^3>";
  return s.str();
}

// Pickling goes through roundedmesh._restore_mesh, a Python function (Boost.Python's own functions cannot
// be pickled by reference), which calls Mesh._restore.
bp::tuple reduce(const bp::object& self) {
  const BodyMesh& m = bp::extract<const BodyMesh&>(self);
  return bp::make_tuple(bp::import("roundedmesh").attr("_restore_mesh"),
                        bp::make_tuple(toArray(m.shape().vertices()), toArray(m.shape().triangles()),
                                       toArray(m.shape().radii()), m.inputCentroid(), m.inputOrientation()));
}

// Unpickling: a mesh already in its principal frame, with the pose it was given in.
std::shared_ptr<BodyMesh> restoreMesh(const bp::object& vertices, const bp::object& triangles, const bp::object& radii,
                                      const Vector3r& centroid, const Quaternionr& orientation) {
  std::vector<Triangle> corners = toTriangles(triangles, "triangles");
  const std::vector<Real> r = toPerTriangle(radii, static_cast<int>(corners.size()), "radii");
  return std::make_shared<BodyMesh>(RoundedMesh(toPoints(vertices, "vertices"), std::move(corners), r), centroid,
                                    orientation);
}

}  // namespace

void exposeMesh() {
  bp::class_<BodyMesh, std::shared_ptr<BodyMesh>>(
      "Mesh",
      "A closed triangulated rounded body shape, stored in its principal frame (centre of mass at the origin,\n"
      "principal axes of inertia along x, y, z). Each triangle has a radius of curvature.\n\n"
      "Mesh(vertices, triangles, radius): vertices (n, 3) [m], triangles (m, 3) vertex indices counter-clockwise\n"
      "seen from outside, radius [m]: one value for all triangles or one per triangle.",
      bp::no_init)
      .def("__init__", bp::make_constructor(&makeMesh, bp::default_call_policies(),
                                            (bp::arg("vertices"), bp::arg("triangles"), bp::arg("radius"))))
      .def("icosphere", &makeIcosphere, (bp::arg("radius"), bp::arg("subdivisions")),
           "Icosphere of `radius` [m]: the icosahedron subdivided `subdivisions` times (0..8), nodes on the sphere;\n"
           "12, 42, 162, 642, 2562 nodes for 0..4. Every triangle's radius of curvature is `radius`.")
      .staticmethod("icosphere")
      .def("_restore", &restoreMesh,
           "Mesh._restore(vertices, triangles, radii, centroid, orientation): a mesh already in its principal\n"
           "frame, as pickled or saved with a scene, rebuilt without moving it.")
      .staticmethod("_restore")
      .add_property("vertices", +[](const BodyMesh& m) { return toArray(m.shape().vertices()); },
                    "(n, 3) vertex positions in the principal frame [m]")
      .add_property("triangles", +[](const BodyMesh& m) { return toArray(m.shape().triangles()); },
                    "(m, 3) vertex indices of each triangle, counter-clockwise seen from outside")
      .add_property("radii", +[](const BodyMesh& m) { return toArray(m.shape().radii()); },
                    "(m,) radius of curvature of each triangle [m]; never below the triangle's circumradius")
      .add_property("normals", +[](const BodyMesh& m) { return toArray(perTriangle(m, &RoundedTriangle::normal)); },
                    "(m, 3) outward unit normal of each triangle")
      .add_property("areas", +[](const BodyMesh& m) { return toArray(areas(m)); }, "(m,) triangle areas [m^2]")
      .add_property("sphere_centres",
                    +[](const BodyMesh& m) { return toArray(perTriangle(m, &RoundedTriangle::sphereCentre)); },
                    "(m, 3) centre of each triangle's encompassing sphere, principal frame [m]")
      .add_property("volume", &BodyMesh::volume, "enclosed volume [m^3]")
      .add_property("centroid", &centroid, "centre of mass in the coordinates the mesh was given in [m]")
      .add_property("orientation", +[](const BodyMesh& m) { return m.inputOrientation(); },
                    "rotation from the principal frame to the frame the mesh was given in (Quaternion)")
      .add_property("inertia", &inertia,
                    "principal moments of inertia at unit density [m^5]; times density gives kg m^2")
      .def("__repr__", &repr)
      .def("__reduce__", &reduce);
}

}  // namespace roundedmesh::python
