#include "py/module/NumpyConversion.hpp"

#include <cstring>
#include <limits>

namespace roundedmesh::python {
namespace {

// A C-contiguous array of `dtype` with `dimensions` axes, converted from anything numpy accepts whose
// element kind is one of `kinds` (numpy's dtype.kind letters), so that no conversion truncates silently.
np::ndarray asArray(const bp::object& object, const np::dtype& dtype, int dimensions, const char* kinds,
                    const std::string& name) {
  const std::string expectation = name + ": expected a " + std::to_string(dimensions) + "-dimensional " +
                                  (std::string(kinds) == "iu" ? "integer" : "numeric") + " array";
  bp::object converted;
  try {
    const bp::object numpy = bp::import("numpy");
    converted = numpy.attr("asarray")(object);
    const std::string kind = bp::extract<std::string>(converted.attr("dtype").attr("kind"));
    if (std::string(kinds).find(kind) == std::string::npos) raiseValueError(expectation);
    converted = numpy.attr("ascontiguousarray")(converted, dtype);
  } catch (const bp::error_already_set&) {
    PyErr_Clear();
    raiseValueError(expectation);
  }
  if (bp::len(converted.attr("shape")) != dimensions) raiseValueError(expectation);
  return bp::extract<np::ndarray>(converted);
}

}  // namespace

void raiseValueError(const std::string& message) {
  PyErr_SetString(PyExc_ValueError, message.c_str());
  bp::throw_error_already_set();
  throw;  // unreachable: throw_error_already_set throws
}

std::vector<Vector3r> toPoints(const bp::object& object, const std::string& name) {
  const np::ndarray array = asArray(object, np::dtype::get_builtin<double>(), 2, "fiu", name);
  if (array.shape(1) != 3) raiseValueError(name + ": expected an (n, 3) array");
  std::vector<Vector3r> points(array.shape(0));
  const double* data = reinterpret_cast<const double*>(array.get_data());
  for (size_t i = 0; i < points.size(); ++i) points[i] = Vector3r(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
  return points;
}

std::vector<Triangle> toTriangles(const bp::object& object, const std::string& name) {
  const np::ndarray array = asArray(object, np::dtype::get_builtin<long>(), 2, "iu", name);
  if (array.shape(1) != 3) raiseValueError(name + ": expected an (m, 3) array of vertex indices");
  std::vector<Triangle> triangles(array.shape(0));
  const long* data = reinterpret_cast<const long*>(array.get_data());
  for (size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const long index = data[3 * i + k];
      if (index < 0 || index > std::numeric_limits<int>::max())
        raiseValueError(name + ": triangle " + std::to_string(i) + " has the invalid vertex index " +
                        std::to_string(index));
      triangles[i][k] = static_cast<int>(index);
    }
  return triangles;
}

std::vector<Real> toPerTriangle(const bp::object& object, int triangleCount, const std::string& name) {
  bp::extract<double> scalar(object);
  if (scalar.check()) return std::vector<Real>(triangleCount, scalar());
  const np::ndarray array = asArray(object, np::dtype::get_builtin<double>(), 1, "fiu", name);
  if (array.shape(0) != triangleCount)
    raiseValueError(name + ": expected one value or " + std::to_string(triangleCount) + " values, got " +
                    std::to_string(array.shape(0)));
  const double* data = reinterpret_cast<const double*>(array.get_data());
  return std::vector<Real>(data, data + triangleCount);
}

namespace {

// An (n, 3) array of Scalar from n rows that index like arrays (Vector3r, Triangle).
template <class Scalar, class Row>
np::ndarray rowsToArray(const std::vector<Row>& rows) {
  np::ndarray array = np::empty(bp::make_tuple(rows.size(), 3), np::dtype::get_builtin<Scalar>());
  Scalar* data = reinterpret_cast<Scalar*>(array.get_data());
  for (size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) data[3 * i + k] = rows[i][k];
  return array;
}

}  // namespace

np::ndarray toArray(const std::vector<Vector3r>& points) { return rowsToArray<double>(points); }
np::ndarray toArray(const std::vector<Triangle>& triangles) { return rowsToArray<long>(triangles); }

np::ndarray toArray(const std::vector<Real>& values) {
  np::ndarray array = np::empty(bp::make_tuple(values.size()), np::dtype::get_builtin<double>());
  std::memcpy(array.get_data(), values.data(), values.size() * sizeof(double));
  return array;
}

np::ndarray toArray(const std::vector<long>& values) {
  np::ndarray array = np::empty(bp::make_tuple(values.size()), np::dtype::get_builtin<long>());
  std::memcpy(array.get_data(), values.data(), values.size() * sizeof(long));
  return array;
}

}  // namespace roundedmesh::python
