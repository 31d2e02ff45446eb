// The compiled part of the Python package: roundedmesh._core. Import yade first: return values use
// YADE's Vector3 and Quaternion converters.
#include <boost/python.hpp>
#include <boost/python/numpy.hpp>

namespace roundedmesh::python {
void exposeMesh();
void exposeMaterial();
void exposeEngineOptions();
void exposeContactStep();
}  // namespace roundedmesh::python

BOOST_PYTHON_MODULE(_core) {
  boost::python::numpy::initialize();
  roundedmesh::python::exposeMesh();
  roundedmesh::python::exposeMaterial();
  roundedmesh::python::exposeEngineOptions();
  roundedmesh::python::exposeContactStep();
}
