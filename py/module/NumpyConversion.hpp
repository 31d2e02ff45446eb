// numpy <-> core arrays for the bindings. Inputs are converted with numpy's own rules (lists, tuples and
// arrays of any numeric type are accepted) and checked for shape; errors name the argument.
#pragma once

#include <boost/python.hpp>
#include <boost/python/numpy.hpp>
#include <string>
#include <vector>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh::python {

namespace bp = boost::python;
namespace np = boost::python::numpy;

std::vector<Vector3r> toPoints(const bp::object& array, const std::string& name);
std::vector<Triangle> toTriangles(const bp::object& array, const std::string& name);
// A scalar (the same for all) or one value per triangle.
std::vector<Real> toPerTriangle(const bp::object& values, int triangleCount, const std::string& name);

np::ndarray toArray(const std::vector<Vector3r>& points);
np::ndarray toArray(const std::vector<Triangle>& triangles);
np::ndarray toArray(const std::vector<Real>& values);
np::ndarray toArray(const std::vector<long>& values);

// Raises Python's ValueError with `message`.
[[noreturn]] void raiseValueError(const std::string& message);

}  // namespace roundedmesh::python
