// libFuzzer target: the STL reader (binary and ASCII, core/geometry/stl.h) and the closest-point
// search built on what it read (core/geometry/mesh_search.h).
#include "core/geometry/mesh_search.h"
#include "core/geometry/stl.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view bytes) {
    metrofit::geometry::TriangleMesh mesh = metrofit::geometry::parseStl(bytes, "fuzz.stl");
    const Eigen::Vector3d lo = mesh.boxMin(), hi = mesh.boxMax();
    const metrofit::geometry::MeshSearch search(std::move(mesh));
    for (const Eigen::Vector3d& x :
         {lo, hi, Eigen::Vector3d((lo + hi) / 2.0), Eigen::Vector3d(0.0, 0.0, 0.0)})
      (void)search.closest(x);
  });
}
