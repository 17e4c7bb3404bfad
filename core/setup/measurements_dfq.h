#pragma once
// The measured features of a setup report series as a Q-DAS DFQ part (core/io/dfq.h), as
// `setup --dfq` and the setup page's "Export Q-DAS DFQ" write it. Plain C++, no Qt.
#include <string>

#include "core/io/dfq.h"
#include "core/setup/model.h"
#include "core/setup/report.h"

namespace metrofit::setup {

/// One characteristic per model dimension that was measured, its values in report order. With a nominal
/// in the model the values are the measured sizes and the limits nominal + lower / upper; without one
/// the values are the deviations (measured - nominal) with nominal 0 and the limits lower / upper (no
/// limits for a zero-width tolerance). K1001 is `partNumber` (the model file's name without extension).
DfqPart measurementsDfqPart(const Model& model, const Measurements& measurements,
                            const std::string& partNumber);

}  // namespace metrofit::setup
