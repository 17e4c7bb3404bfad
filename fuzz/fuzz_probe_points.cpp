// libFuzzer target: the contact-probed point reader (CSV with normals, position-only, planar).
#include "core/io/csv.h"
#include "core/matching/probe_points.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::ProbePointSet s = metrofit::probePointsFromCsv(metrofit::parseCsv(text, "fuzz.csv"));
    (void)metrofit::probePointsToCsv(s);
  });
}
