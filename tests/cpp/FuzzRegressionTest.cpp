// Every input the fuzzers of fuzz/ found a problem with (doc/reliability.md), replayed from tests/data/fuzz/:
// each is now refused with std::invalid_argument naming what is wrong, as any broken mesh must be.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/SoupFormat.hpp"
#include "pkg/io/MeshFile.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

const std::string kData = ROUNDEDMESH_TEST_DATA "/fuzz/";

using test::refusal;

// obj_reader_fuzzer: a closed, consistently oriented surface that passes through itself, with a positive
// volume but negative principal moments of inertia. It used to become a body with negative moments.
TEST(FuzzRegression, SelfIntersectingObjIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "self_intersecting.obj"); });
  EXPECT_NE(message.find("self_intersecting.obj: the surface intersects itself"), std::string::npos) << message;
}

// surface_repair_fuzzer: the same defect as a polygon soup (two octahedra, one turned through the other).
TEST(FuzzRegression, SelfIntersectingSoupIsRefused) {
  std::ifstream in(kData + "self_intersecting.soup", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  const PolygonSoup soup = fuzz::decodeSoup(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  EXPECT_NE(refusal([&] { repairedSurface(soup); }).find("intersects itself"), std::string::npos);
}

// ply_reader_fuzzer: a "property" line before any "element" made CGAL's PLY reader call back() on an empty
// vector (a read through a garbage pointer).
TEST(FuzzRegression, PlyPropertyBeforeElementIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "property_before_element.ply"); });
  EXPECT_NE(message.find("property_before_element.ply: PLY header line 4 declares a property before any element"),
            std::string::npos) << message;
}

// off_reader_fuzzer: a vertex line too many shifts the faces, and the face "1.0 -1.0 0.0" gives CGAL's OFF
// scanner a corner index of -1, which it converts to std::size_t (undefined behaviour in CGAL, suppressed in
// the sanitized builds by fuzz/ubsan.supp): the file must still be refused by name.
TEST(FuzzRegression, OffNegativeCornerIndexIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "negative_index_cast.off"); });
  EXPECT_EQ(message.rfind(kData + "negative_index_cast.off: ", 0), 0u) << message;
}

// off_reader_fuzzer: a corner count of -41 became a huge size in CGAL's OFF reader, whose vector then threw
// std::length_error out of readMeshFile (an exception no caller expects of a broken file).
TEST(FuzzRegression, OffNegativeCountIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "negative_count.off"); });
  EXPECT_EQ(message.rfind(kData + "negative_count.off: cannot be read as off", 0), 0u) << message;
}

// off_reader_fuzzer (in CI's 15 s): an OFF header whose vertex count, 3.3e117, has no std::uint64_t; the search for
// a non-finite vertex that names its line (after CGAL refused the file) converted it anyway (undefined behaviour).
TEST(FuzzRegression, OffVertexCountBeyondAnIntegerIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "huge_vertex_count.off"); });
  EXPECT_EQ(message.rfind(kData + "huge_vertex_count.off: cannot be read as off", 0), 0u) << message;
}

// off_reader_fuzzer (in CI's 15 s): a binary OFF header declaring 1229865216 edges, which CGAL's header reader
// doubles as an int (signed overflow in CGAL, suppressed by fuzz/ubsan.supp); the file must still be refused.
// Likewise its halfedge estimate (vertices + facets + 10) * 2.1 converted to int (halfedge_estimate.off).
TEST(FuzzRegression, OffHeaderCountOverflowsAreRefused) {
  for (const std::string file : {"edge_count_overflow.off", "halfedge_estimate.off"}) {
    const std::string message = refusal([&] { readMeshFile(kData + file); });
    EXPECT_EQ(message.rfind(kData + file + ": ", 0), 0u) << message;
  }
}

// off_reader_fuzzer (after our own OFF loop): a COFF file whose vertex lines hold no colour made CGAL's
// scan_color index an empty line (applying an offset to a null pointer); text files' colours are not read now.
TEST(FuzzRegression, OffColourMissingFromItsLineIsRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "colour_entries_missing.off"); });
  EXPECT_EQ(message.rfind(kData + "colour_entries_missing.off: ", 0), 0u) << message;
}

// ply_reader_fuzzer: CGAL's PLY reader trusts the header. A vertex coordinate declared uint32 was cast to the
// float it expects and the null result dereferenced; a negative element count ran its loops for 2^64
// elements (a timeout) or sized its arrays by it (3 GB asked by a 300-byte file), and so did a count that is not a
// whole number ("-1end..."), which a double reads as 0.
TEST(FuzzRegression, PlyHeadersCgalWouldTrustAreRefused) {
  for (const auto& [file, line] : {std::pair<std::string, std::string>{"integer_coordinate.ply", "5 declares the "
                                                                       "vertex coordinate x as 'uint32'"},
                                   {"huge_element_count.ply", "3 declares -5.000000 elements 'vertex'"},
                                   {"slow_element_count.ply", "4 declares -1.000000 elements 'vert'"},
                                   // issue 27's CI run: "-1end_hea.0" reads 0 as a double, 2^64 - 1 to CGAL
                                   {"element_count_not_a_number.ply", "3 declares the element count '-1end_hea.0' "
                                                                      "for 'vert': not a whole number"}}) {
    const std::string message = refusal([&] { readMeshFile(kData + file); });
    EXPECT_EQ(message.rfind(kData + file + ": PLY header line " + line, 0), 0u) << message;
  }
}

// ply_reader_fuzzer, long run of this release: CGAL's PLY reader also trusts a face's corner count. A binary file of
// 442 bytes whose first list count reads 540,356,145 (the bytes "1.5 ") asked for 2.16 GB.
TEST(FuzzRegression, PlyListCountsBeyondTheFileAreRefused) {
  const std::string message = refusal([] { readMeshFile(kData + "huge_list_count.ply"); });
  EXPECT_EQ(message.rfind(kData + "huge_list_count.ply: PLY element 'fa' row 0 holds a list of 540356145", 0), 0u)
      << message;
}

}  // namespace
}  // namespace roundedmesh
