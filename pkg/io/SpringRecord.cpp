#include "pkg/io/SpringRecord.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace roundedmesh {
namespace {

constexpr char kHeader[] = "RMSPRING1";
constexpr size_t kHeaderSize = sizeof kHeader - 1;
constexpr size_t kEntrySize = 2 * sizeof(std::int32_t) + 8 * sizeof(double);
static_assert(sizeof(Real) == sizeof(double), "the record holds doubles");

// Base64 (RFC 4648, padded), by table: Boost's dataflow iterators (boost/archive/iterators) took 0.3 ms per step
// for the 1,000 springs of a settled S1 packing, three times Python's binascii.
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string toBase64(const std::string& bytes) {
  const auto* in = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t whole = bytes.size() / 3, rest = bytes.size() % 3;
  std::string text((whole + (rest > 0)) * 4, '=');
  char* out = text.data();
  for (size_t g = 0; g < whole; ++g, in += 3, out += 4) {
    const std::uint32_t group = std::uint32_t(in[0]) << 16 | std::uint32_t(in[1]) << 8 | in[2];
    out[0] = kAlphabet[group >> 18];
    out[1] = kAlphabet[group >> 12 & 63];
    out[2] = kAlphabet[group >> 6 & 63];
    out[3] = kAlphabet[group & 63];
  }
  if (rest > 0) {
    const std::uint32_t group = std::uint32_t(in[0]) << 16 | (rest == 2 ? std::uint32_t(in[1]) << 8 : 0);
    out[0] = kAlphabet[group >> 18];
    out[1] = kAlphabet[group >> 12 & 63];
    if (rest == 2) out[2] = kAlphabet[group >> 6 & 63];
  }
  return text;
}

std::string fromBase64(const std::string& text) {
  if (text.size() % 4 != 0) throw std::invalid_argument("its length is not a multiple of 4");
  std::array<int, 256> value;
  value.fill(-1);
  for (int k = 0; k < 64; ++k) value[static_cast<unsigned char>(kAlphabet[k])] = k;
  std::string bytes;
  bytes.reserve(text.size() / 4 * 3);
  for (size_t at = 0; at < text.size(); at += 4) {
    const bool last = at + 4 == text.size();
    const size_t padding = last ? (text[at + 3] == '=') + (text[at + 2] == '=') : 0;
    std::uint32_t group = 0;
    for (size_t k = 0; k < 4; ++k) {
      const int v = k < 4 - padding ? value[static_cast<unsigned char>(text[at + k])] : 0;
      if (v < 0) throw std::invalid_argument(text[at + k] == '=' ? "'=' inside the text" : "a character outside base64's alphabet");
      group = group << 6 | static_cast<std::uint32_t>(v);
    }
    for (size_t k = 0; k < 3 - padding; ++k) bytes += static_cast<char>(group >> (16 - 8 * k) & 255);
  }
  return bytes;
}

}  // namespace

std::string encodeSprings(const std::vector<SpringEntry>& springs) {
  std::string bytes(kHeader);
  bytes.reserve(kHeaderSize + springs.size() * kEntrySize);
  for (const SpringEntry& e : springs) {
    const std::int32_t ids[2] = {e.id1, e.id2};
    const TangentialSpring& s = e.spring;
    const double values[8] = {s.displacement.x(), s.displacement.y(), s.displacement.z(), s.twist,
                              s.normal.x(),       s.normal.y(),       s.normal.z(),       s.energy};
    bytes.append(reinterpret_cast<const char*>(ids), sizeof ids);
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
  }
  return toBase64(bytes);
}

std::vector<SpringEntry> decodeSprings(const std::string& record) {
  std::string bytes;
  try {
    bytes = fromBase64(record);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("not a spring record: ") + e.what());
  }
  if (bytes.compare(0, kHeaderSize, kHeader) != 0) throw std::invalid_argument("not a spring record: no RMSPRING1 header");
  if ((bytes.size() - kHeaderSize) % kEntrySize != 0)
    throw std::invalid_argument("not a spring record: " + std::to_string(bytes.size() - kHeaderSize) +
                                " bytes after the header, not a whole number of springs");
  std::vector<SpringEntry> springs;
  springs.reserve((bytes.size() - kHeaderSize) / kEntrySize);
  for (size_t at = kHeaderSize; at < bytes.size(); at += kEntrySize) {
    std::int32_t ids[2];
    double v[8];
    std::memcpy(ids, bytes.data() + at, sizeof ids);
    std::memcpy(v, bytes.data() + at + sizeof ids, sizeof v);
    TangentialSpring spring;
    spring.displacement = Vector3r(v[0], v[1], v[2]);
    spring.twist = v[3];
    spring.normal = Vector3r(v[4], v[5], v[6]);
    spring.energy = v[7];
    springs.push_back({ids[0], ids[1], spring});
  }
  return springs;
}

}  // namespace roundedmesh
