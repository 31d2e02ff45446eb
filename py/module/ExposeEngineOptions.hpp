// roundedmesh.EngineOptions, and the options of a call made from Python keywords (ExposeEngineOptions.cpp).
#pragma once

#include <boost/python.hpp>

#include "pkg/engine/EngineOptions.hpp"

namespace roundedmesh::python {
namespace bp = boost::python;

// The options named in `keywords` ({name: value}), the others at their defaults, validated. Raises Python's
// TypeError for an unknown name or a value of the wrong type, ValueError (std::invalid_argument) for a value out of
// range, each naming the option.
EngineOptions engineOptions(const bp::dict& keywords);

void exposeEngineOptions();

}  // namespace roundedmesh::python
