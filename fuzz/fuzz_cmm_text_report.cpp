// libFuzzer target: the CMM text report reader (core/io/cmm_text_report.h: OGP step and summary
// reports, plain or RTF, and PC-DMIS text reports) and its feature-series table.
#include <string>

#include "core/io/cmm_text_report.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    if (metrofit::looksLikeCmmTextReport(text))
      (void)metrofit::cmmReportFeatureTable(metrofit::cmmTextReportFromText(text, "fuzz.txt"));
    (void)metrofit::rtfToText(text, "fuzz.rtf");
  });
}
