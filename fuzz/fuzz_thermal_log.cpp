// libFuzzer target: the thermal log reader (CSV -> ThermalLog with its validation).
#include "core/io/csv.h"
#include "core/thermal/thermal_log.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::ThermalLog log = metrofit::thermalLogFromCsv(metrofit::parseCsv(text, "fuzz.csv"));
    (void)metrofit::thermalLogToCsv(log);
  });
}
