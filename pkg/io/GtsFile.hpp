// GTS files (GNU Triangulated Surface library; YADE's yade.ymport.gts, pack.inGtsSurface and the gts module use
// them), read and written by our own code: CGAL has no GTS reader. readMeshFile and writeMeshFile (MeshFile.hpp)
// call these for the extension .gts; the surface read then goes through repairedSurface like every format.
//
// The format, as libgts's gts_surface_write writes it and gts_surface_read reads it:
//   NV NE NF [GtsSurface GtsFace GtsEdge GtsVertex]   the counts, then optionally the class names
//   x y z                                            NV lines: the vertices
//   v1 v2                                            NE lines: the edges, 1-based vertex numbers
//   e1 e2 e3                                         NF lines: the faces, 1-based edge numbers
// '#' starts a comment, to the end of its line (libgts's GtsFile does the same); blank lines are skipped.
//
// Orientation: a face's corners are met by walking its edges in the order listed, e1, then e2 (and e3 back to
// the start): v1 is the vertex of e1 that e2 does not have, v2 the one they share, v3 the other end of e2.
// Each edge's own vertex order does not matter. Corners in that order are counter-clockwise seen from outside
// on an outward surface: (v2 - v1) x (v3 - v1) points out. That is libgts's gts_triangle_vertices order, and
// its gts_triangle_normal and gts_surface_volume (positive for an outward surface) agree with it. Checked on
// YADE's example files (examples/gts-horse/horse.coarse.gts, pfacet/{box,sphere,octahedron}.gts,
// jointedCohesiveFrictionalPM/parallellepiped.gts): with this order every face's normal points the way libgts's
// gts_triangle_normal does (through YADE's gts module) and the signed volume is positive, equal to libgts's.
//
// Reading is strict: a wrong or missing count, a number that is not one (or not finite, or out of double's
// range), an index out of range, an edge from a vertex to itself, a face whose three edges do not close into a
// triangle, a line with more entries than its kind has (derived GTS classes' extra data are not read), the
// file ending early, or anything after the last face throws std::invalid_argument "PATH: line N: ...". Numbers
// in these messages are the file's own (vertices and edges counted from 1); repairedSurface's messages, which
// follow, count vertices and faces from 0 in the file's order, like every format's.
#pragma once

#include <string>

#include "pkg/meshing/SurfaceRepair.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

// The file's vertices (unscaled) and its faces as corner triples in the order above, not yet checked as a
// surface (that is repairedSurface's part).
PolygonSoup readGtsSoup(const std::string& path);

// Writes the vertices in their order, the edges in the order the triangles first use them (each edge's vertices
// in increasing order), and each triangle (a, b, c) as the edges ab, bc, ca: read back, its corners come out as
// a, b, c. Coordinates with 17 significant digits, so that readGtsSoup returns them bit for bit.
void writeGtsFile(const std::string& path, const TriangleSurface& surface);

}  // namespace roundedmesh
