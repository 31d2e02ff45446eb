#include "pkg/io/GtsFile.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "pkg/io/TextTokens.hpp"

namespace roundedmesh {
namespace {

std::string counted(std::uint64_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

// A count or a 1-based number: decimal digits only (no sign), within 64 bits.
bool parseCount(std::string_view token, std::uint64_t& value) {
  if (token.empty() || !std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

// The file's lines that hold something once comments ('#' to the end of the line) are removed, as tokens, with
// their line numbers; refusals name the path and the line.
class GtsLines {
 public:
  explicit GtsLines(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_.is_open()) throw std::invalid_argument(path + ": cannot be opened");
  }

  // The next line with data; false at the end of the file.
  bool next() {
    tokens_.clear();
    while (std::getline(in_, line_)) {
      ++number_;
      const std::size_t comment = line_.find('#');
      if (comment != std::string::npos) line_.resize(comment);
      const std::string_view line(line_);
      std::size_t position = 0;
      while (position < line.size()) {
        const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
        while (position < line.size() && blank(line[position])) ++position;
        const std::size_t start = position;
        while (position < line.size() && !blank(line[position])) ++position;
        if (position > start) tokens_.push_back(line.substr(start, position - start));
      }
      if (!tokens_.empty()) return true;
    }
    if (in_.bad()) throw std::invalid_argument(path_ + ": cannot be read");
    return false;
  }

  const std::vector<std::string_view>& tokens() const { return tokens_; }

  [[noreturn]] void refuse(const std::string& what) const {
    throw std::invalid_argument(path_ + ": line " + std::to_string(number_) + ": " + what);
  }

  // The file ended (next() returned false) after `read` of the `declared` things of a kind (`plural`).
  [[noreturn]] void refuseEnd(std::uint64_t read, std::uint64_t declared, const char* plural) const {
    refuse("the file ends after " + std::to_string(read) + " of the " + std::to_string(declared) + " " + plural +
           " that its first line declares (truncated?)");
  }

 private:
  std::string path_;
  std::ifstream in_;
  std::string line_;
  std::vector<std::string_view> tokens_;
  std::uint64_t number_ = 0;
};

// A GTS class name on the first line: letters, digits and underscores, not starting with a digit.
bool isClassName(std::string_view token) {
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  return letter(token[0]) &&
         std::all_of(token.begin(), token.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

// A 1-based index into `count` things on a data line ("a vertex" or "an edge" number), returned 0-based.
std::size_t parseIndex(const GtsLines& lines, std::string_view token, std::uint64_t count, const std::string& whose,
                       const char* what) {
  std::uint64_t index = 0;
  if (!parseCount(token, index) || index < 1 || index > count)
    lines.refuse(whose + ": " + shown(token) + " is not " + what + " number " +
                 (count == 0 ? std::string("(there are none)") : "from 1 to " + std::to_string(count)));
  return static_cast<std::size_t>(index - 1);
}

// Refuses a data line with more or fewer entries than its kind has.
void requireEntries(const GtsLines& lines, std::size_t expected, const std::string& whose, const char* entries,
                    const char* layout) {
  const auto& tokens = lines.tokens();
  if (tokens.size() < expected)
    lines.refuse(whose + " has " + counted(tokens.size(), "entry", "entries") + "; its line must hold " +
                 std::to_string(expected) + " " + entries + " (" + layout + ")");
  if (tokens.size() > expected)
    lines.refuse(whose + ": unexpected " + shown(tokens[expected]) + " after its " + std::to_string(expected) + " " +
                 entries + " (" + layout + "); the data of GTS classes other than GtsVertex, GtsEdge and GtsFace "
                 "is not read");
}

}  // namespace

PolygonSoup readGtsSoup(const std::string& path) {
  std::error_code error;
  const std::uintmax_t fileSize = std::filesystem::file_size(path, error);
  GtsLines lines(path);
  if (!lines.next())
    lines.refuse("the file holds no data; a GTS file starts with the numbers of vertices, edges and faces");

  // The first line: NV NE NF, then class names only.
  std::array<std::uint64_t, 3> counts{};
  const auto& header = lines.tokens();
  static constexpr std::array<const char*, 3> kCounted = {"vertices", "edges", "faces"};
  for (std::size_t k = 0; k < 3; ++k) {
    if (k >= header.size())
      lines.refuse("the first line must start with the numbers of vertices, edges and faces (NV NE NF); it holds " +
                   counted(header.size(), "entry", "entries"));
    if (!parseCount(header[k], counts[k]))
      lines.refuse(std::string("the number of ") + kCounted[k] + " on the first line, " + shown(header[k]) +
                   ", is not a whole number");
  }
  for (std::size_t k = 3; k < header.size(); ++k)
    if (!isClassName(header[k]))
      lines.refuse("unexpected " + shown(header[k]) +
                   " after the numbers of vertices, edges and faces (only GTS class names may follow them)");
  const auto [vertexCount, edgeCount, faceCount] = counts;
  // The shortest lines are "0 0 0", "1 2" and "1 2 3", each with its line break (the last may lack one): a
  // count the file cannot hold is refused before anything is sized by it (each count first on its own, so that
  // the sum cannot overflow).
  if (vertexCount > fileSize || edgeCount > fileSize || faceCount > fileSize ||
      6 * vertexCount + 4 * edgeCount + 6 * faceCount > fileSize + 1)
    lines.refuse("the counts declare " + counted(vertexCount, "vertex", "vertices") + ", " +
                 counted(edgeCount, "edge", "edges") + " and " + counted(faceCount, "face", "faces") +
                 ", more than a file of " + std::to_string(fileSize) + " bytes can hold");

  PolygonSoup soup;
  soup.points.reserve(vertexCount);
  for (std::uint64_t v = 0; v < vertexCount; ++v) {
    if (!lines.next()) lines.refuseEnd(v, vertexCount, "vertices");
    const std::string whose = "vertex " + std::to_string(v + 1);
    requireEntries(lines, 3, whose, "coordinates", "x y z");
    Vector3r& point = soup.points.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = lines.tokens()[k];
      const Parsed parsed = parseReal(token, point[k]);
      if (parsed == Parsed::notANumber) lines.refuse(whose + ": the coordinate " + shown(token) + " is not a number");
      if (parsed == Parsed::outOfRange)
        lines.refuse(whose + ": the coordinate " + shown(token) + " is out of the range of a double");
      if (!std::isfinite(point[k])) lines.refuse(whose + " has a non-finite coordinate " + shown(token));
    }
  }

  std::vector<std::array<std::size_t, 2>> edges;
  edges.reserve(edgeCount);
  for (std::uint64_t e = 0; e < edgeCount; ++e) {
    if (!lines.next()) lines.refuseEnd(e, edgeCount, "edges");
    const std::string whose = "edge " + std::to_string(e + 1);
    requireEntries(lines, 2, whose, "vertex numbers", "v1 v2, counted from 1");
    const std::size_t a = parseIndex(lines, lines.tokens()[0], vertexCount, whose, "a vertex");
    const std::size_t b = parseIndex(lines, lines.tokens()[1], vertexCount, whose, "a vertex");
    if (a == b) lines.refuse(whose + " joins vertex " + std::to_string(a + 1) + " to itself");
    edges.push_back({a, b});
  }

  // Each face's corners in the order of its edges (the orientation convention of GtsFile.hpp).
  soup.polygons.reserve(faceCount);
  for (std::uint64_t f = 0; f < faceCount; ++f) {
    if (!lines.next()) lines.refuseEnd(f, faceCount, "faces");
    const std::string whose = "face " + std::to_string(f + 1);
    requireEntries(lines, 3, whose, "edge numbers", "e1 e2 e3, counted from 1");
    std::array<std::size_t, 3> e{};
    for (int k = 0; k < 3; ++k) e[k] = parseIndex(lines, lines.tokens()[k], edgeCount, whose, "an edge");
    const auto& first = edges[e[0]];
    const auto& second = edges[e[1]];
    const auto& third = edges[e[2]];
    // v2: the vertex the first two edges share; v1 and v3 their other ends; the third edge must join v3 to v1.
    bool closes = true;
    std::size_t v1 = first[0], v2 = first[1];
    if (v2 != second[0] && v2 != second[1]) std::swap(v1, v2);
    if (v2 != second[0] && v2 != second[1]) closes = false;
    const std::size_t v3 = second[0] == v2 ? second[1] : second[0];
    if (v3 == v1 || !((third[0] == v3 && third[1] == v1) || (third[0] == v1 && third[1] == v3))) closes = false;
    if (!closes) {
      std::string list;
      for (int k = 0; k < 3; ++k)
        list += (k == 0 ? "" : k == 1 ? ", " : " and ") + std::to_string(e[k] + 1) + " (vertices " +
                std::to_string(edges[e[k]][0] + 1) + ", " + std::to_string(edges[e[k]][1] + 1) + ")";
      lines.refuse(whose + "'s edges " + list + " do not close into a triangle");
    }
    soup.polygons.push_back({v1, v2, v3});
  }

  if (lines.next())
    lines.refuse("unexpected " + shown(lines.tokens()[0]) + " after the " + counted(faceCount, "face", "faces") +
                 " that the first line declares");
  return soup;
}

void writeGtsFile(const std::string& path, const TriangleSurface& surface) {
  // Edges numbered in the order the triangles first use them, keyed by their two vertices (smaller first).
  std::unordered_map<std::uint64_t, std::size_t> edgeNumber;
  std::vector<std::array<std::uint64_t, 2>> edges;
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    std::array<std::size_t, 3>& face = faces.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(t[k]), b = static_cast<std::uint64_t>(t[(k + 1) % 3]);
      const std::array<std::uint64_t, 2> edge = {std::min(a, b), std::max(a, b)};
      const auto [entry, added] = edgeNumber.try_emplace(edge[0] << 32 | edge[1], edges.size());
      if (added) edges.push_back(edge);
      face[k] = entry->second;
    }
  }

  std::string text = std::to_string(surface.vertices.size()) + " " + std::to_string(edges.size()) + " " +
                      std::to_string(faces.size()) + " GtsSurface GtsFace GtsEdge GtsVertex\n";
  char number[32];
  for (const Vector3r& v : surface.vertices)
    for (int k = 0; k < 3; ++k) {
      // 17 significant digits, independent of the locale: read back exactly.
      const auto result = std::to_chars(number, number + sizeof number, v[k], std::chars_format::general, 17);
      text.append(number, result.ptr);
      text += k < 2 ? ' ' : '\n';
    }
  for (const auto& edge : edges) text += std::to_string(edge[0] + 1) + " " + std::to_string(edge[1] + 1) + "\n";
  for (const auto& face : faces)
    text += std::to_string(face[0] + 1) + " " + std::to_string(face[1] + 1) + " " + std::to_string(face[2] + 1) + "\n";

  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::invalid_argument(path + ": cannot be written");
}

}  // namespace roundedmesh
