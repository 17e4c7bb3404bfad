// libFuzzer target: the Zeiss Calypso table readers (core/io/calypso.h): _chr characteristics (and their
// report form and feature table), _fet features as probe points, _hdr dates.
#include <string>

#include "core/io/calypso.h"
#include "core/io/cmm_text_report.h"
#include "core/matching/probe_points.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    (void)metrofit::cmmReportFeatureTable(
        metrofit::calypsoCmmReport(metrofit::calypsoCharacteristicsFromText(text, "fuzz_chr.txt")));
  });
  metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    (void)metrofit::probePointsFromCsv(metrofit::calypsoFeaturesProbeTable(text, "fuzz_fet.txt"), 1);
  });
  return metrofit::fuzz::expectValueOrInputError(
      data, size, [](std::string_view text) { (void)metrofit::calypsoHeaderDates(text, "fuzz_hdr.txt"); });
}
