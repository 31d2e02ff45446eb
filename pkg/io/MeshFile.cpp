#include "pkg/io/MeshFile.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <vector>

#include "pkg/io/GtsFile.hpp"
#include "pkg/io/TextTokens.hpp"
#include "pkg/meshing/SurfaceRepair.hpp"

namespace roundedmesh {
namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
constexpr std::array<const char*, 5> kFormats = {"obj", "stl", "off", "ply", "gts"};

std::string format(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (std::find(kFormats.begin(), kFormats.end(), extension) == kFormats.end())
    throw std::invalid_argument(path + ": unknown mesh format '" + extension +
                                "'; use .obj, .stl, .off, .ply or .gts");
  return extension;
}

// The size of a PLY scalar type [bytes]; 0 for a name PLY does not have.
int plyTypeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

struct PlyProperty {
  int countSize = 0;  // bytes of a list's count; 0 for a scalar
  bool countSigned = false;
  int size = 0;       // bytes of the scalar, or of each list item
};

struct PlyElement {
  std::string name;
  std::uintmax_t count = 0;
  std::vector<PlyProperty> properties;
};

// Every list count in the file's data, in its order of elements, rows and properties, must be at most the file's
// size: nothing in a file can need more entries than it has bytes. CGAL resizes a face's corner list by the count
// as it stands (2 GB asked for by a binary file of 442 bytes: ply_reader_fuzzer). Data that ends early is left
// to CGAL, which refuses it.
void requireBoundedPlyLists(std::istream& in, const std::string& format, const std::vector<PlyElement>& elements,
                            std::uintmax_t fileSize, const std::string& path) {
  const bool ascii = format == "ascii", little = format == "binary_little_endian";
  // The next value as a number: a text token, or `size` bytes as an integer in the file's byte order.
  auto next = [&](int size, bool isSigned, double& value) {
    if (ascii) return static_cast<bool>(in >> value);
    unsigned char bytes[8];
    if (!in.read(reinterpret_cast<char*>(bytes), size)) return false;
    std::uint64_t bits = 0;
    for (int i = 0; i < size; ++i) bits |= std::uint64_t(bytes[little ? i : size - 1 - i]) << (8 * i);
    const bool negative = isSigned && (bits >> (8 * size - 1)) & 1;
    value = negative ? -double((~bits + 1) & (size == 8 ? ~0ull : (1ull << (8 * size)) - 1)) : double(bits);
    return true;
  };
  for (const PlyElement& element : elements)
    for (std::uintmax_t row = 0; row < element.count; ++row)
      for (const PlyProperty& property : element.properties) {
        double value = 0;
        if (property.countSize == 0) {
          if (ascii ? !(in >> value) : !in.ignore(property.size)) return;
          continue;
        }
        if (!next(property.countSize, property.countSigned, value)) return;
        if (!(value >= 0 && value <= double(fileSize)))
          throw std::invalid_argument(path + ": PLY element '" + element.name + "' row " + std::to_string(row) +
                                      " holds a list of " + std::to_string(value) + " items in a file of " +
                                      std::to_string(fileSize) + " bytes");
        const auto items = static_cast<std::uintmax_t>(value);
        for (std::uintmax_t i = 0; i < items; ++i)
          if (ascii ? !(in >> value) : !in.ignore(property.size)) return;
      }
}

// CGAL 5.5's PLY reader trusts the header and the data (each case found by fuzz/ply_reader_fuzzer,
// doc/reliability.md): a property before any element is added to the last element of an empty vector; an element's
// count, or a list's, sizes arrays and loops however few bytes follow (gigabytes, or minutes, from a file of a few
// hundred bytes); and a vertex coordinate that is not a float or double, or a face's corner list that is not a list,
// is cast to the type it expects and the null result dereferenced. Such files are refused here, before CGAL reads
// them.
void requireReadablePly(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  std::string line, format;
  std::vector<PlyElement> elements;
  for (int number = 1; std::getline(in, line); ++number) {
    auto refuse = [&](const std::string& what) {
      throw std::invalid_argument(path + ": PLY header line " + std::to_string(number) + " " + what);
    };
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") return requireBoundedPlyLists(in, format, elements, fileSize, path);
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      std::string name, countWord;
      words >> name >> countWord;
      double count = -1;
      std::istringstream(countWord) >> count;
      if (!(count >= 0 && count <= double(fileSize)))
        refuse("declares " + std::to_string(count) + " elements '" + name + "' in a file of " +
               std::to_string(fileSize) + " bytes");
      // CGAL reads the count as a std::size_t, where "-1e..." is 2^64 - 1 (a loop without end) and "7x" is 7,
      // while a double reads the first as 0: only a whole number is the same count to both.
      if (countWord.find_first_not_of("0123456789") != std::string::npos)
        refuse("declares the element count '" + countWord + "' for '" + name + "': not a whole number");
      elements.push_back({name, static_cast<std::uintmax_t>(count), {}});
    } else if (keyword == "property") {
      if (elements.empty()) refuse("declares a property before any element");
      const std::string& element = elements.back().name;
      std::string type, countType, name;
      words >> type;
      const bool list = type == "list";
      if (list) words >> countType >> type;
      words >> name;
      PlyProperty property{list ? plyTypeSize(countType) : 0, !countType.empty() && countType[0] != 'u',
                           plyTypeSize(type)};
      if (property.size == 0 || (list && property.countSize == 0))
        refuse("declares the property " + name + " of a type PLY does not have");
      const bool real = type == "float" || type == "float32" || type == "double" || type == "float64";
      if (element == "vertex" && (name == "x" || name == "y" || name == "z") && (list || !real))
        refuse("declares the vertex coordinate " + name + " as " + (list ? "a list" : "'" + type + "'") +
               "; it must be a float or a double");
      if (element == "face" && (name == "vertex_indices" || name == "vertex_index") && !list)
        refuse("declares the face's " + name + " as one '" + type + "'; it must be a list");
      elements.back().properties.push_back(property);
    }
  }
}

// CGAL 5.5's read_OFF, with every count it takes from the file checked against the file's size before it
// sizes a vector by it: CGAL's own reader resizes to the header's counts and to each face's corner count as
// they stand, and a negative one (converted to std::size_t, undefined behaviour it does not check; see
// fuzz/ubsan.supp) or an absurd one asks for terabytes (found by fuzz/off_reader_fuzzer, doc/reliability.md).
// Nothing in a file can need more entries than it has bytes. Normals, colours and textures are skipped: in a
// binary file by reading them, in a text file by not asking for them, since CGAL's scan_normal, scan_color
// and scan_texture then index the line scan_vertex or scan_facet has read without checking that it holds
// them (a read through a null pointer on a COFF vertex line without colour: off_reader_fuzzer).
bool readOff(std::istream& in, std::uintmax_t fileSize, std::vector<Point>& points,
             std::vector<std::vector<std::size_t>>& polygons) {
  CGAL::File_scanner_OFF scanner(in);
  if (in.fail() || scanner.size_of_vertices() + scanner.size_of_facets() > fileSize) return false;
  points.resize(scanner.size_of_vertices());
  polygons.resize(scanner.size_of_facets());
  for (Point& point : points) {
    double x = 0, y = 0, z = 0, w = 1, ignored = 0;
    unsigned char colour = 0;
    scanner.scan_vertex(x, y, z, w);
    point = Point(x / w, y / w, z / w);
    if (scanner.binary() && scanner.has_normals()) scanner.scan_normal(ignored, ignored, ignored);
    if (scanner.binary() && scanner.has_vcolors()) scanner.scan_color(colour, colour, colour);
    if (scanner.binary() && scanner.has_textures()) scanner.scan_texture(ignored, ignored);
    if (!in.good()) return false;
  }
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    std::size_t corners = std::size_t(-1);
    scanner.scan_facet(corners, f);
    if ((!in.eof() && !in.good()) || corners > fileSize) return false;
    polygons[f].resize(corners);
    for (std::size_t j = 0; j < corners; ++j) {
      std::size_t index = 0;
      scanner.scan_facet_vertex_index(index, j + 1, f);
      if (!in || index >= points.size()) return false;
      polygons[f][j] = index;
    }
    if (scanner.binary() && scanner.has_fcolors()) {
      unsigned char colour = 0;
      scanner.scan_color(colour, colour, colour);
    }
  }
  return !in.fail();
}

// The first vertex of a text OBJ, STL or OFF file with a coordinate that is not a finite number ('nan', 'inf'):
// CGAL's readers stop there without saying where, so a file they could not read is searched for it and the line
// named, as the GTS reader names it. Nothing is thrown if no vertex has one (the file is broken otherwise).
// Vertices are the 'v' lines of OBJ, the 'vertex' lines of STL, and in OFF the lines after the header and the
// counts ('#' starts a comment in OBJ and OFF).
void requireFiniteTextVertices(const std::string& path, const std::string& kind) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uint64_t vertex = 0, offVertices = 0;
  int offLines = 0;  // OFF's lines that hold something: the header, the counts (on it or the next), the vertices
  for (int number = 1; std::getline(in, line); ++number) {
    if (kind != "stl") line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    const std::vector<std::string> tokens{std::istream_iterator<std::string>(words), {}};
    if (tokens.empty()) continue;
    std::size_t first = 1;
    if (kind == "off") {
      ++offLines;
      const bool header = offLines == 1 && tokens[0].find("OFF") != std::string::npos;
      if (header && tokens.size() > 1) ++offLines;  // the counts follow on the header's line
      if (offLines <= 2) {
        double count = 0;
        const std::string& counts = header ? (tokens.size() > 1 ? tokens[1] : std::string()) : tokens[0];
        // A whole number within a double's exact integers (a count of 1e117 has no std::uint64_t: off_reader_fuzzer).
        if (!counts.empty() && parseReal(counts, count) == Parsed::number && count >= 0 && count <= 0x1p53 &&
            count == std::floor(count))
          offVertices = static_cast<std::uint64_t>(count);
        continue;
      }
      if (vertex >= offVertices) return;
      first = 0;
    } else if (tokens[0] != (kind == "obj" ? "v" : "vertex")) {
      continue;
    }
    ++vertex;
    for (std::size_t k = first; k < std::min(tokens.size(), first + 3); ++k) {
      double value = 0;
      if (parseReal(tokens[k], value) == Parsed::number && !std::isfinite(value))
        throw std::invalid_argument(path + ": line " + std::to_string(number) + ": vertex " + std::to_string(vertex) +
                                    " has a non-finite coordinate " + shown(tokens[k]));
    }
  }
}

// OBJ, STL, OFF or PLY through CGAL's readers (with the checks above), unscaled and not yet repaired.
PolygonSoup readWithCgal(const std::string& path, const std::string& kind) {
  std::error_code error;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  // CGAL's extension dispatch is case-sensitive; readMeshFile has already recognised the format.
  std::ifstream in(path, std::ios::binary);
  bool read = false;
  // CGAL's readers take counts and indices from the file as they stand: a negative count becomes a huge
  // size, and the vector resized to it throws std::length_error or std::bad_alloc (found by
  // fuzz/off_reader_fuzzer, doc/reliability.md). That is a broken file, not a failure of the program.
  try {
    if (kind == "obj") read = CGAL::IO::read_OBJ(in, points, polygons);
    else if (kind == "off") read = readOff(in, std::filesystem::file_size(path, error), points, polygons);
    else if (kind == "ply") {
      requireReadablePly(path, std::filesystem::file_size(path, error));
      read = CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false));
    }
    else read = CGAL::IO::read_STL(in, points, polygons, CGAL::parameters::verbose(false));
  } catch (const std::length_error&) {
    read = false;
  } catch (const std::bad_alloc&) {
    read = false;
  }
  if (!read && kind != "ply") requireFiniteTextVertices(path, kind);
  if (!read)
    throw std::invalid_argument(path + ": cannot be read as " + kind +
                                " (truncated, corrupt, or not a mesh file of that format)");

  PolygonSoup soup;
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  soup.polygons = std::move(polygons);
  return soup;
}

}  // namespace

TriangleSurface readMeshFile(const std::string& path, Real scale, const RepairOptions& repair) {
  if (!(std::isfinite(scale) && scale > 0))
    throw std::invalid_argument("scale must be positive and finite, got " + std::to_string(scale));
  const std::string kind = format(path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw FileNotFound(path + ": no such file");
  if (std::filesystem::file_size(path, error) == 0) throw std::invalid_argument(path + ": the file is empty");

  PolygonSoup soup = kind == "gts" ? readGtsSoup(path) : readWithCgal(path, kind);
  for (Vector3r& p : soup.points) p *= scale;
  try {
    return repairedSurface(soup, repair);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

void writeMeshFile(const std::string& path, const TriangleSurface& surface) {
  if (format(path) == "gts") return writeGtsFile(path, surface);
  std::vector<Point> points;
  points.reserve(surface.vertices.size());
  for (const Vector3r& v : surface.vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles) polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  if (!CGAL::IO::write_polygon_soup(path, points, polygons, CGAL::parameters::stream_precision(17)))
    throw std::invalid_argument(path + ": cannot be written");
}

}  // namespace roundedmesh
