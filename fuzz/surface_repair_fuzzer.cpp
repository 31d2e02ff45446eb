// The mesh checks and repair (repairedSurface, with and without filling flat holes) on polygon soups no reader would
// produce (fuzz/SoupFormat.hpp), and the body made of what they accept; a repaired surface must also pass the checks alone
// (requireValidSurface). Seeds: fuzz/corpus/surface_repair_fuzzer, tests/data's OBJ and OFF files as soups.
#include "fuzz/FuzzSupport.hpp"
#include "fuzz/SoupFormat.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roundedmesh;
  const PolygonSoup soup = fuzz::decodeSoup(data, size);
  for (const bool fillFlatHoles : {false, true})
    fuzz::refusalsOnly([&] {
      const TriangleSurface surface = repairedSurface(soup, RepairOptions{fillFlatHoles});
      try {
        requireValidSurface(surface);
      } catch (const std::invalid_argument& e) {
        fuzz::finding(std::string("a repaired surface fails the checks: ") + e.what());
      }
      fuzz::requireUsableBody(surface);
    });
  return 0;
}
