// libFuzzer target: the Q-DAS DFQ reader (core/io/dfq.h: K fields, value lines, /0 fields, 8-bit text),
// its report form (dfqCmmReport, the feature table) and the characteristic choice.
#include <string>

#include "core/io/cmm_text_report.h"
#include "core/io/dfq.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::DfqFile f = metrofit::dfqFromText(text, "fuzz.dfq");
    (void)metrofit::dfqParts(f);
    (void)metrofit::cmmReportFeatureTable(metrofit::dfqCmmReport(f));
    std::vector<std::pair<std::string, std::string>> list;
    for (const auto& c : f.characteristics) list.emplace_back(c.number, c.description);
    (void)metrofit::chooseCharacteristic(list, "1", "fuzz.dfq");
  });
}
