// libFuzzer target: the project file reader (JSON -> metrofit::Project, with validation).
#include "core/io/json_util.h"
#include "core/project/project.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::Project p =
        metrofit::Project::fromJson(metrofit::parseJson(text, "fuzz.metrofit"), "fuzz.metrofit");
    (void)metrofit::dumpJson(p.toJson());
  });
}
