// libFuzzer target: the PC-DMIS hole-table text report reader (core/matching/hole_table.h).
#include <string>

#include "core/matching/hole_table.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const std::string s(text);
    if (metrofit::looksLikeHoleTable(s)) (void)metrofit::holeTableFromText(s, "fuzz.txt");
    (void)metrofit::holeTableFromText(s, "fuzz.txt");
  });
}
