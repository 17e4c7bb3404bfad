// libFuzzer target: the DMIS output reader of the setup study (FA/TA records mapped to the
// dimensions of the bundled paper example).
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "fuzz_common.h"

namespace {
const metrofit::setup::Model& paperModel() {
  static const metrofit::setup::Model model =
      metrofit::setup::readModel(METROFIT_SOURCE_DIR "/resources/demo/setup/paper_example.json");
  return model;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const metrofit::setup::Model& model = paperModel();
  return metrofit::fuzz::expectValueOrInputError(data, size, [&](std::string_view text) {
    (void)metrofit::setup::dmisReportFromText(text, "fuzz.dmo", model);
  });
}
