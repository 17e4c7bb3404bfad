// libFuzzer target: the QIF 3 Results reader (core/io/qif.h: XML, units, id references), its report form
// (qifCmmReport, the feature table) and the probe points of each part (core/matching/qif_points.h).
#include <string>

#include "core/io/cmm_text_report.h"
#include "core/io/qif.h"
#include "core/matching/qif_points.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    (void)metrofit::looksLikeQif(text);
    const metrofit::QifFile f = metrofit::qifFromText(text, "fuzz.qif");
    (void)metrofit::cmmReportFeatureTable(metrofit::qifCmmReport(f));
    for (std::size_t p = 0; p < f.parts.size(); ++p) {
      try {
        (void)metrofit::qifProbePoints(f, p);
      } catch (const metrofit::InputError&) {
        // a part without located features: a clean error
      }
    }
    (void)metrofit::qifPartIndex(f, 1);
  });
}
