// libFuzzer target: the setup model (relation graph JSON) reader with its validation and gain matrix.
#include "core/io/json_util.h"
#include "core/setup/model.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return metrofit::fuzz::expectValueOrInputError(data, size, [](std::string_view text) {
    const metrofit::setup::Model m =
        metrofit::setup::modelFromJson(metrofit::parseJson(text, "fuzz.json"), "fuzz.json");
    metrofit::setup::validateModel(m);
    (void)metrofit::setup::gainMatrix(m);
  });
}
