// The record of the tangential springs (pkg/io/SpringRecord.hpp), the text a saved scene brings back into the
// engine from O.tags: any text is either refused with a message (std::invalid_argument) or decoded, and what
// decodes encodes to a record that decodes to the same springs, bit for bit. Seeds: fuzz/corpus.
#include <cstring>
#include <string>

#include "fuzz/FuzzSupport.hpp"
#include "pkg/io/SpringRecord.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roundedmesh;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::refusalsOnly([&] {
    const std::vector<SpringEntry> springs = decodeSprings(text);
    const std::vector<SpringEntry> again = decodeSprings(encodeSprings(springs));
    if (again.size() != springs.size()) fuzz::finding("a decoded record lost springs on the way back");
    for (std::size_t k = 0; k < springs.size(); ++k) {
      const SpringEntry &a = springs[k], &b = again[k];
      const bool same = a.id1 == b.id1 && a.id2 == b.id2 &&
                        std::memcmp(a.spring.displacement.data(), b.spring.displacement.data(), 3 * sizeof(Real)) == 0 &&
                        std::memcmp(a.spring.normal.data(), b.spring.normal.data(), 3 * sizeof(Real)) == 0 &&
                        std::memcmp(&a.spring.twist, &b.spring.twist, sizeof(Real)) == 0 &&
                        std::memcmp(&a.spring.energy, &b.spring.energy, sizeof(Real)) == 0;
      if (!same) fuzz::finding("spring " + std::to_string(k) + " changed in a round trip");
    }
  });
  return 0;
}
