// libFuzzer target: the CSV reader (core/io/csv.h) and its number parsing.
#include "core/io/csv.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::CsvTable t = metrofit::parseCsv(text, "fuzz.csv");
    for (std::size_t c = 0; c < t.columnCount(); ++c) (void)t.numericColumn(c);
  });
}
