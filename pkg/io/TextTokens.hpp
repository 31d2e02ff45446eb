// Tokens of text mesh files, as the readers that name the line of an error parse and show them (GtsFile.cpp,
// MeshFile.cpp).
#pragma once

#include <string>
#include <string_view>

namespace roundedmesh {

// A token as a message shows it: quoted, at most 24 characters, bytes that are not printable ASCII as \xNN.
std::string shown(std::string_view token);

enum class Parsed { number, notANumber, outOfRange };

// A coordinate as strtod (libgts's reader) takes it, but independent of the locale: an optional sign, decimal
// or scientific notation; "nan" and "inf" are numbers here and refused as non-finite by the caller.
Parsed parseReal(std::string_view token, double& value);

}  // namespace roundedmesh
