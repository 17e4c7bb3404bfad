// libFuzzer target: the MTConnect readers (core/io/mtconnect.h): SHDR lines (pairs, conditions, asset
// blocks, commands, timestamps) or a Streams document, the resampled sample table and the thermal log
// made of it (core/thermal/thermal_log.h, gaps as NaN, written back as CSV).
#include <algorithm>
#include <string>

#include "core/io/mtconnect.h"
#include "core/thermal/thermal_log.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    (void)metrofit::looksLikeShdr(text);
    const bool streams = metrofit::looksLikeMtconnectStreams(text);
    const metrofit::MtcLog log = streams ? metrofit::mtconnectStreamsFromText(text, "fuzz.xml")
                                         : metrofit::shdrFromText(text, "fuzz.txt");
    // A grid of at most about a thousand rows whatever the log's span (fuzzed timestamps span centuries;
    // the reader's own limit is about the CLI's interval, not the fuzzer's memory).
    double first = 0.0, last = 0.0;
    bool any = false;
    for (const metrofit::MtcObservation& o : log.observations) {
      first = any ? std::min(first, o.timeS) : o.timeS;
      last = any ? std::max(last, o.timeS) : o.timeS;
      any = true;
    }
    const double interval = std::max(1.0, (last - first) / 1000.0);
    const metrofit::MtcSampleTable table = metrofit::mtconnectSampleTable(log, interval);
    const metrofit::ThermalLog thermal = metrofit::thermalLogFromMtconnect(table, 1);
    (void)metrofit::thermalLogToCsv(thermal);
  });
}
