// roundedmesh.Mesh: a closed rounded mesh in its principal frame (pkg/meshing/BodyMesh.hpp), from arrays,
// files or the shape generators.
#include <boost/python.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "pkg/io/MeshFile.hpp"
#include "pkg/meshing/ImplicitCurvature.hpp"
#include "pkg/meshing/BlendedShape.hpp"
#include "pkg/meshing/RoundedTetrahedron.hpp"
#include "pkg/meshing/Superellipsoid.hpp"
#include "pkg/meshing/SurfaceRemesher.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/CapTolerance.hpp"
#include "pkg/shape/Curvature.hpp"
#include "pkg/shape/Cylinder.hpp"
#include "pkg/shape/Distortion.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "pkg/meshing/Spheroid.hpp"
#include "pkg/meshing/SurfaceRepair.hpp"
#include "py/module/NumpyConversion.hpp"

namespace roundedmesh::python {
namespace {

using MeshPtr = std::shared_ptr<BodyMesh>;

std::optional<Real> optionalReal(const bp::object& value) {
  if (value.is_none()) return std::nullopt;
  return bp::extract<Real>(value)();
}

// radius: None (compute the curvature from the mesh, Eq. 1), one radius, or one per triangle [m]; an
// infinite radius is flat, a negative one concave.
std::optional<std::vector<Real>> prescribedCurvatures(const bp::object& radius, int triangleCount) {
  if (radius.is_none()) return std::nullopt;
  std::vector<Real> curvatures = toPerTriangle(radius, triangleCount, "radius");
  for (std::size_t t = 0; t < curvatures.size(); ++t) {
    if (std::isnan(curvatures[t]) || curvatures[t] == 0)
      raiseValueError("radius: triangle " + std::to_string(t) + " has radius " + std::to_string(curvatures[t]) +
                      "; use a positive radius, inf for flat, a negative one for concave, or None to compute it");
    curvatures[t] = 1 / curvatures[t];
  }
  return curvatures;
}

MeshPtr bodyMesh(const TriangleSurface& surface, const bp::object& radius, const bp::object& maxRadius,
                 const bp::object& tolerance, bool remesh) {
  std::optional<CapPolicy> caps;
  if (!tolerance.is_none()) caps = CapPolicy{bp::extract<Real>(tolerance)(), remesh};
  return std::make_shared<BodyMesh>(surface, prescribedCurvatures(radius, static_cast<int>(surface.triangles.size())),
                                    optionalReal(maxRadius), std::nullopt, caps);
}

// The generators' curvature: "exact" (the smooth shape's, prescribed) or "computed" (Eq. 1 from the mesh).
MeshPtr generated(const TriangleSurface& surface, const std::string& curvature, std::vector<Real> exact,
                  std::optional<std::vector<PrincipalCurvature>> exactPrincipal = std::nullopt) {
  if (curvature == "computed") return std::make_shared<BodyMesh>(surface, std::nullopt);
  if (curvature == "exact") return std::make_shared<BodyMesh>(surface, std::move(exact), std::nullopt, std::move(exactPrincipal));
  raiseValueError("curvature must be 'exact' or 'computed', got '" + curvature + "'");
}

MeshPtr fromArrays(const bp::object& vertices, const bp::object& triangles, const bp::object& radius,
                   const bp::object& maxRadius, const bp::object& tolerance, bool remesh) {
  PolygonSoup soup;
  soup.points = toPoints(vertices, "vertices");
  for (const Triangle& t : toTriangles(triangles, "triangles")) {
    for (int corner : t)
      if (corner < 0) raiseValueError("triangles: negative vertex index " + std::to_string(corner));
    soup.polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  }
  TriangleSurface surface;
  try {
    surface = repairedSurface(soup);
  } catch (const std::invalid_argument& e) {
    raiseValueError(std::string("mesh: ") + e.what());
  }
  return bodyMesh(surface, radius, maxRadius, tolerance, remesh);
}

MeshPtr load(const std::string& path, Real scale, const bp::object& radius, const bp::object& maxRadius,
             bool fillHoles, const bp::object& tolerance, bool remesh) {
  return bodyMesh(readMeshFile(path, scale, RepairOptions{fillHoles}), radius, maxRadius, tolerance, remesh);
}

void save(const BodyMesh& mesh, const std::string& path) { writeMeshFile(path, mesh.inputFrameSurface()); }

MeshPtr makeIcosphere(Real radius, int subdivisions, Real distortion, unsigned seed, const std::string& curvature) {
  const TriangleSurface s = distortion == 0 ? icosphereSurface(radius, subdivisions)
                                            : distortedIcosphereSurface(radius, subdivisions, distortion, seed);
  return generated(s, curvature, std::vector<Real>(s.triangles.size(), 1 / radius));
}

MeshPtr makeSpheroid(Real a, Real b, int nodes, const std::string& curvature) {
  const TriangleSurface s = spheroidSurface(a, b, nodes);
  return generated(s, curvature, spheroidTriangleCurvatures(a, b, s), spheroidTrianglePrincipalCurvatures(a, b, s));
}

MeshPtr makeCylinder(Real radius, Real length, int nodes, const std::string& curvature) {
  const TriangleSurface s = cylinderSurface(radius, length, nodes);
  return generated(s, curvature, cylinderTriangleCurvatures(radius, s), cylinderTrianglePrincipalCurvatures(radius, s));
}

// Mesh._blended_shape(blend, primitives, nodes, volume): primitives as (a, b, radius) triples in shape units;
// returns (mesh, scale). roundedmesh.Mesh.reference_shape reads them from shapes.json.
// A mesh of an implicit solid's surface `s` (scaled by `scale` [m per shape unit]) with its curvature 'computed'
// (Eq. 1) or 'exact' (f's shape operator under each triangle, ImplicitCurvature.hpp).
MeshPtr implicitGenerated(const ImplicitSolid& solid, const TriangleSurface& s, Real scale, const std::string& curvature) {
  if (curvature == "computed") return std::make_shared<BodyMesh>(s, std::nullopt);
  if (curvature != "exact") raiseValueError("curvature must be 'exact' or 'computed', got '" + curvature + "'");
  SurfaceCurvatures exact = implicitSurfaceCurvatures(solid, s, scale, 1e-4 * solid.thickness);
  return std::make_shared<BodyMesh>(s, std::move(exact.mean), std::nullopt, std::move(exact.principal));
}

bp::tuple makeBlendedShape(Real blend, const bp::list& primitives, int nodes, Real volume, const std::string& curvature) {
  BlendedShape shape{blend, {}};
  for (int i = 0; i < bp::len(primitives); ++i) {
    const bp::object p = primitives[i];
    shape.primitives.push_back({bp::extract<Vector3r>(p[0])(), bp::extract<Vector3r>(p[1])(), bp::extract<Real>(p[2])()});
  }
  Real scale = 0;
  const TriangleSurface s = blendedShapeSurface(shape, nodes, volume, &scale);
  return bp::make_tuple(implicitGenerated(implicitSolid(shape), s, scale, curvature), scale);
}

MeshPtr makeImplicit(const ImplicitSolid& solid, int nodes, const std::string& curvature) {
  return implicitGenerated(solid, meshImplicitSurface(solid, nodes), 1, curvature);
}

MeshPtr makeSuperellipsoid(Real a, Real b, Real c, Real exponent, int nodes, const std::string& curvature) {
  return makeImplicit(implicitSolid(Superellipsoid{a, b, c, exponent}), nodes, curvature);
}

MeshPtr makeRoundedTetrahedron(Real inradius, Real rounding, int nodes, const std::string& curvature) {
  return makeImplicit(implicitSolid(RoundedTetrahedron{inradius, rounding}), nodes, curvature);
}

// Mesh.remeshed(nodes): the surface, in its input frame, remeshed to about `nodes` nodes, curvature computed.
MeshPtr remeshed(const BodyMesh& mesh, int nodes) {
  return std::make_shared<BodyMesh>(remeshedToNodes(mesh.inputFrameSurface(), nodes), std::nullopt, std::nullopt,
                                    std::nullopt, CapPolicy{kDefaultCapTolerance, true});
}

template <class Value>
std::vector<Value> perTriangle(const BodyMesh& mesh, Value RoundedTriangle::*field) {
  std::vector<Value> out(mesh.shape().triangleCount());
  for (int t = 0; t < mesh.shape().triangleCount(); ++t) out[t] = mesh.shape().rounded(t).*field;
  return out;
}

TriangleSurface bodySurface(const BodyMesh& m) { return {m.shape().vertices(), m.shape().triangles()}; }

std::vector<Real> triangleCapHeights(const BodyMesh& m) { return capHeights(bodySurface(m), m.shape().radii()); }

np::ndarray centroid(const BodyMesh& m) { return toArray(std::vector<Real>(m.inputCentroid().data(), m.inputCentroid().data() + 3)); }
np::ndarray inertia(const BodyMesh& m) { return toArray(std::vector<Real>(m.principalMoments().data(), m.principalMoments().data() + 3)); }
std::string curvatureMode(const BodyMesh& m) {
  return m.curvature().source == CurvatureSource::Computed ? "computed" : "prescribed";
}

std::string repr(const BodyMesh& m) {
  std::ostringstream s;
  s << "<roundedmesh.Mesh: " << m.shape().vertices().size() << " vertices, " << m.shape().triangleCount()
    << " triangles, volume " << m.volume() << " m^3, " << curvatureMode(m) << " curvature>";
  return s.str();
}

// (m, 2) principal curvatures k1 >= k2 of each triangle [1/m], and (m, 3) the direction of k1, principal frame.
np::ndarray principalValues(const BodyMesh& m) {
  const std::vector<PrincipalCurvature>& k = m.shape().principalCurvatures();
  np::ndarray out = np::empty(bp::make_tuple(k.size(), 2), np::dtype::get_builtin<Real>());
  Real* data = reinterpret_cast<Real*>(out.get_data());
  for (std::size_t t = 0; t < k.size(); ++t) {
    data[2 * t] = k[t].k1;
    data[2 * t + 1] = k[t].k2;
  }
  return out;
}

np::ndarray principalDirections(const BodyMesh& m) {
  std::vector<Vector3r> d;
  for (const PrincipalCurvature& k : m.shape().principalCurvatures()) d.push_back(k.d1);
  return toArray(d);
}

// Pickling goes through roundedmesh._restore_mesh, a Python function (Boost.Python's own functions cannot
// be pickled by reference), which calls Mesh._restore.
bp::tuple reduce(const bp::object& self) {
  const BodyMesh& m = bp::extract<const BodyMesh&>(self);
  return bp::make_tuple(bp::import("roundedmesh").attr("_restore_mesh"),
                        bp::make_tuple(toArray(m.shape().vertices()), toArray(m.shape().triangles()),
                                       toArray(m.shape().radii()), m.inputCentroid(), m.inputOrientation(),
                                       toArray(m.curvature().meanCurvatures), curvatureMode(m),
                                       m.curvature().maxRadius, principalValues(m), principalDirections(m)));
}

// Unpickling: a mesh already in its principal frame, with the pose it was given in (roundedmesh._restore_mesh
// fills in what older records lack).
MeshPtr restoreMesh(const bp::object& vertices, const bp::object& triangles, const bp::object& radii,
                    const Vector3r& centroid, const Quaternionr& orientation, const bp::object& curvatures,
                    const std::string& mode, Real maxRadius, const bp::object& k1, const bp::object& k2,
                    const bp::object& directions) {
  std::vector<Triangle> corners = toTriangles(triangles, "triangles");
  const int count = static_cast<int>(corners.size());
  std::vector<PrincipalCurvature> principal;
  if (!k1.is_none()) {
    const std::vector<Real> larger = toPerTriangle(k1, count, "k1"), smaller = toPerTriangle(k2, count, "k2");
    const std::vector<Vector3r> d1 = toPoints(directions, "principal directions");
    if (static_cast<int>(d1.size()) != count) raiseValueError("principal directions: one per triangle expected");
    for (int t = 0; t < count; ++t) principal.push_back({larger[t], smaller[t], d1[t]});
  }
  RoundedMesh shape(toPoints(vertices, "vertices"), std::move(corners), toPerTriangle(radii, count, "radii"),
                    std::move(principal));
  SurfaceCurvature curvature;
  curvature.meanCurvatures = toPerTriangle(curvatures, count, "curvatures");
  if (mode != "computed" && mode != "prescribed")
    raiseValueError("mode must be 'computed' or 'prescribed', got '" + mode + "'");
  curvature.source = mode == "computed" ? CurvatureSource::Computed : CurvatureSource::Prescribed;
  curvature.maxRadius = maxRadius;
  return std::make_shared<BodyMesh>(shape, centroid, orientation, std::move(curvature));
}

void translateFileNotFound(const FileNotFound& e) { PyErr_SetString(PyExc_FileNotFoundError, e.what()); }

const char* const kRadiusDoc =
    "radius: None to compute each triangle's curvature from the mesh (Eq. 1), or a radius of curvature [m] for\n"
    "all triangles or one per triangle (inf: flat, negative: concave). max_radius [m]: the radius flat and\n"
    "concave triangles use in contact (default 100 volume-equivalent radii); see doc/physics.md.\n"
    "tolerance: with the curvature computed from the mesh, how far (a fraction of the volume-equivalent radius\n"
    "r_eq) the rounded body may lie beyond the mesh (Mesh.deviation). Where a cap would rise higher (a mesh too\n"
    "coarse for its curvature: sharp edges, slivers, a coarse scan), the mesh is remeshed finer with the same shape\n"
    "and its sharp edges kept (remesh=True, Mesh.remesh_passes), and any cap still beyond gets the smallest radius\n"
    "that keeps it within (Mesh.bounded_caps). Default 0.05 (half the Hertz depth); None takes the mesh and its\n"
    "radii as they are. Prescribed radii are never changed.";

}  // namespace

void exposeMesh() {
  bp::register_exception_translator<FileNotFound>(&translateFileNotFound);
  bp::scope().attr("DEFAULT_MESH_TOLERANCE") = kDefaultCapTolerance;
  const std::string arraysDoc = std::string(
      "Mesh.from_arrays(vertices, triangles, radius=None, max_radius=None, tolerance=0.05, remesh=True):\n"
      "vertices (n, 3) [m], triangles (m, 3) vertex indices counter-clockwise seen from outside. Checked and\n"
      "repaired like a file (see Mesh.load).\n") + kRadiusDoc;
  const std::string loadDoc = std::string(
      "Mesh.load(path, scale=1.0, radius=None, max_radius=None, fill_holes=False, tolerance=0.05, remesh=True):\n"
      "reads OBJ, STL (ASCII or binary), OFF, PLY or\n"
      "GTS (GNU Triangulated Surface, as yade.ymport.gts reads it) by the extension, and multiplies coordinates\n"
      "by scale (0.001 for millimetres). Duplicate vertices are welded, faces with more than 3 corners\n"
      "triangulated, triangles turned to agree with their neighbours and an inside-out surface reversed; a\n"
      "surface that is not closed, edge-manifold and orientable, has degenerate triangles, non-finite\n"
      "coordinates or no volume raises ValueError\n"
      "naming the file, the defect and where it is (in a malformed GTS file, the line). fill_holes=True closes\n"
      "each hole that is flat and seen whole from its centroid (an open end cut flat) with a fan from that\n"
      "centroid; any other hole is still refused.\n") + kRadiusDoc;
  bp::class_<BodyMesh, MeshPtr>(
      "Mesh",
      "A closed triangulated rounded body shape, stored in its principal frame (centre of mass at the origin,\n"
      "principal axes of inertia along x, y, z: in ascending order of moment, x the long axis of an elongated\n"
      "body, except that a mesh whose inertia is already diagonal keeps its axes). Each triangle has a radius\n"
      "of curvature.\n\n"
      "Mesh(vertices, triangles, radius=None, max_radius=None, tolerance=0.05, remesh=True) is Mesh.from_arrays.",
      bp::no_init)
      .def("__init__", bp::make_constructor(&fromArrays, bp::default_call_policies(),
                                            (bp::arg("vertices"), bp::arg("triangles"), bp::arg("radius") = bp::object(),
                                             bp::arg("max_radius") = bp::object(),
                                             bp::arg("tolerance") = kDefaultCapTolerance,
                                             bp::arg("remesh") = true)))
      .def("from_arrays", &fromArrays, (bp::arg("vertices"), bp::arg("triangles"), bp::arg("radius") = bp::object(),
                                        bp::arg("max_radius") = bp::object(), bp::arg("tolerance") = kDefaultCapTolerance,
                                        bp::arg("remesh") = true),
           arraysDoc.c_str())
      .staticmethod("from_arrays")
      .def("load", &load, (bp::arg("path"), bp::arg("scale") = 1.0, bp::arg("radius") = bp::object(),
                       bp::arg("max_radius") = bp::object(), bp::arg("fill_holes") = false,
                       bp::arg("tolerance") = kDefaultCapTolerance, bp::arg("remesh") = true), loadDoc.c_str())
      .staticmethod("load")
      .def("save", &save, (bp::arg("path")),
           "Writes the (repaired) surface, in the frame it was given in, as OBJ, STL, OFF, PLY or GTS by the path's\n"
           "extension. STL keeps single precision; the others read back exactly. GTS files are read by YADE\n"
           "(yade.ymport.gts, pack.inGtsSurface) with the same outward orientation.")
      .def("icosphere", &makeIcosphere,
           (bp::arg("radius"), bp::arg("subdivisions"), bp::arg("distortion") = 0.0, bp::arg("seed") = 0,
            bp::arg("curvature") = "exact"),
           "Icosphere of `radius` [m]: the icosahedron subdivided `subdivisions` times (0..8), nodes on the sphere;\n"
           "12, 42, 162, 642, 2562 nodes for 0..4. distortion > 0: nodes moved at random along the sphere until\n"
           "the distortion D (Eq. 26) is that value (Fig. 4a), reproducibly for a given seed.\n"
           "curvature: 'exact' (every triangle has the sphere's radius) or 'computed' (Eq. 1 from the mesh).")
      .staticmethod("icosphere")
      .def("spheroid", &makeSpheroid, (bp::arg("a"), bp::arg("b"), bp::arg("nodes"), bp::arg("curvature") = "exact"),
           "Spheroid with semi-axis a [m] along its axis and b [m] across (the mesh is not exactly symmetric, so its\n"
           "principal axes are ordered: the axis on x when a > b, on z when a < b), about `nodes` nodes (typically\n"
           "within 2 %), near-\n"
           "equilateral triangles. curvature: 'exact' (the spheroid's mean curvature under each triangle) or\n"
           "'computed' (Eq. 1 from the mesh). Both principal curvatures likewise (exact, or estimated from the mesh).")
      .staticmethod("spheroid")
      .def("cylinder", &makeCylinder,
           (bp::arg("radius"), bp::arg("length"), bp::arg("nodes"), bp::arg("curvature") = "exact"),
           "Closed cylinder along z with flat caps (its inertia is diagonal as made, so it stays along z), about\n"
           "`nodes` nodes (within 3 % from 100 nodes on). curvature: 'exact'\n"
           "(mean curvature 1/(2 radius) on the hull, flat caps) or 'computed' (Eq. 1 from the mesh).")
      .staticmethod("cylinder")
      .def("superellipsoid", &makeSuperellipsoid,
           (bp::arg("a"), bp::arg("b"), bp::arg("c"), bp::arg("exponent"), bp::arg("nodes"), bp::arg("curvature") = "exact"),
           "Superellipsoid |x/a|^p + |y/b|^p + |z/c|^p = 1 (Barr 1981): semi-axes a, b, c [m], exponent p >= 2 (2 an\n"
           "ellipsoid; 3-8 a pill or rounded box, flatter faces and tighter edges as p grows), about `nodes` nodes\n"
           "(typically within 2 %), near-equilateral triangles, every node on the surface. Volume\n"
           "8 a b c Gamma(1 + 1/p)^3 / Gamma(1 + 3/p). curvature: 'exact' (mean and principal curvatures of the smooth\n"
           "surface under each triangle) or 'computed' (Eq. 1 from the mesh).")
      .staticmethod("superellipsoid")
      .def("rounded_tetrahedron", &makeRoundedTetrahedron,
           (bp::arg("inradius"), bp::arg("rounding"), bp::arg("nodes"), bp::arg("curvature") = "exact"),
           "A rounded tetrahedral grain: the smooth maximum s ln sum_i exp(n_i . x / s) = h of the face planes of a\n"
           "regular tetrahedron of inradius h [m] (`inradius`), rounded over the length s [m] (`rounding`, in\n"
           "(0, h / ln 3)): strictly convex, nearly flat faces, rounded edges, tight corners. About `nodes` nodes;\n"
           "curvature 'exact' or 'computed' as for superellipsoid.")
      .staticmethod("rounded_tetrahedron")
      .def("remeshed", &remeshed, bp::arg("nodes"),
           "mesh.remeshed(nodes) -> Mesh: the same surface remeshed with CGAL's isotropic remeshing to about `nodes`\n"
           "nodes (within 10 % from 300 nodes on; coarser targets and kept sharp edges leave more), curvature computed\n"
           "(Eq. 1), caps held within "
           "the default tolerance as Mesh.load does. New nodes lie on the old surface: coarsening a fine mesh keeps its\n"
           "shape; refining a coarse one adds nodes on its flat triangles, and the curvature computed from it then\n"
           "concentrates on the old edges (it cannot recover a smooth shape the mesh does not hold).")
      .def("_blended_shape", &makeBlendedShape,
           (bp::arg("blend"), bp::arg("primitives"), bp::arg("nodes"), bp::arg("volume"), bp::arg("curvature") = "computed"),
           "Mesh._blended_shape(blend, primitives, nodes, volume, curvature='computed') -> (mesh, scale); see\n"
           "Mesh.reference_shape.")
      .staticmethod("_blended_shape")
      .def("_restore", &restoreMesh,
           (bp::arg("vertices"), bp::arg("triangles"), bp::arg("radii"), bp::arg("centroid"), bp::arg("orientation"),
            bp::arg("curvatures"), bp::arg("mode"), bp::arg("max_radius"), bp::arg("k1") = bp::object(),
            bp::arg("k2") = bp::object(), bp::arg("principal_directions") = bp::object()),
           "A mesh already in its principal frame, as pickled or saved with a scene, rebuilt without moving it.")
      .staticmethod("_restore")
      .add_property("vertices", +[](const BodyMesh& m) { return toArray(m.shape().vertices()); },
                    "(n, 3) vertex positions in the principal frame [m]")
      .add_property("triangles", +[](const BodyMesh& m) { return toArray(m.shape().triangles()); },
                    "(m, 3) vertex indices of each triangle, counter-clockwise seen from outside")
      .add_property("radii", +[](const BodyMesh& m) { return toArray(m.shape().radii()); },
                    "(m,) radius of curvature each triangle uses in contact [m]: 1/curvature, max_radius for flat\n"
                    "and concave triangles, never below the triangle's circumradius")
      .add_property("curvatures", +[](const BodyMesh& m) { return toArray(m.curvature().meanCurvatures); },
                    "(m,) signed mean curvature of each triangle [1/m]: computed (Eq. 1) or prescribed; < 0 concave")
      .add_property("node_curvatures", +[](const BodyMesh& m) { return toArray(meanCurvature(bodySurface(m)).nodes); },
                    "(n,) signed mean curvature at each node computed from the mesh (Eq. 1) [1/m], whatever the mode")
      .add_property("principal_curvatures", &principalValues,
                    "(m, 2) both principal curvatures k1 >= k2 of each triangle [1/m] (< 0 concave), for\n"
                    "engine(curvature='principal'): prescribed by the generators with curvature='exact', both equal to\n"
                    "the mean curvature when that is prescribed, else estimated from the mesh (Rusinkiewicz 2004)")
      .add_property("principal_directions", &principalDirections,
                    "(m, 3) unit direction of k1 on each triangle, principal frame; k2's is normal x direction")
      .add_property("curvature_mode", &curvatureMode, "'computed' (Eq. 1 from the mesh) or 'prescribed'")
      .add_property("max_radius", +[](const BodyMesh& m) { return m.curvature().maxRadius; },
                    "radius flat and concave triangles use in contact [m]")
      .add_property("distortion", +[](const BodyMesh& m) { return distortion(bodySurface(m)); },
                    "D = std(triangle area) / mean(triangle area) (Eq. 26)")
      .add_property("inscribed_spheres",
                    +[](const BodyMesh& m) {
                      const InscribedSpheres& core = m.shape().inscribedSpheres();
                      return bp::make_tuple(toArray(core.centres), toArray(core.radii));
                    },
                    "(centres (k, 3) [m], radii (k,) [m]), principal frame: the spheres inscribed in the mesh that its\n"
                    "core is made of (doc/physics.md, 'Deep overlaps and fast impacts', The core), largest first; the core's spheres are\n"
                    "these shrunk by rm.engine(core_inset=...) of their radii")
      .add_property("normals", +[](const BodyMesh& m) { return toArray(perTriangle(m, &RoundedTriangle::normal)); },
                    "(m, 3) outward unit normal of each triangle")
      .add_property("areas", +[](const BodyMesh& m) { return toArray(perTriangle(m, &RoundedTriangle::area)); },
                    "(m,) triangle areas [m^2]")
      .add_property("cap_heights", +[](const BodyMesh& m) { return toArray(triangleCapHeights(m)); },
                    "(m,) height of each triangle's cap over the triangle [m] (pkg/shape/CapTolerance.hpp): how far the\n"
                    "rounded body reaches beyond the flat triangle, and so how far from the mesh it can push a partner")
      .add_property("deviation",
                    +[](const BodyMesh& m) {
                      const std::vector<Real> h = triangleCapHeights(m);
                      return *std::max_element(h.begin(), h.end());
                    },
                    "the tallest cap [m]: the two-sided distance between the rounded body and the flat mesh (no point\n"
                    "of either lies farther from the other)")
      .add_property("remesh_passes", &BodyMesh::remeshPasses,
                    "how many times the input was remeshed finer to bring its caps within the tolerance (0: loaded\n"
                    "as it is; also for generated, prescribed or unpickled meshes)")
      .add_property("remesh_edge_length", &BodyMesh::remeshEdgeLength, "target edge length of the last pass [m]")
      .add_property("bounded_caps", &BodyMesh::boundedCaps,
                    "how many triangles' radii were raised, after any remeshing, to keep their caps within the\n"
                    "tolerance (Mesh.load, Mesh.from_arrays); 0 for generated, prescribed or unpickled meshes")
      .add_property("sphere_centres",
                    +[](const BodyMesh& m) { return toArray(perTriangle(m, &RoundedTriangle::sphereCentre)); },
                    "(m, 3) centre of each triangle's encompassing sphere, principal frame [m]")
      .add_property("bound_radius", +[](const BodyMesh& m) { return m.shape().sphereBoundRadius(); },
                    "radius of the ball about the centre of mass that holds the whole rounded body [m]: no partner\n"
                    "outside it can touch the body")
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
