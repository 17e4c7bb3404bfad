#include "core/setup/measurements_dfq.h"

#include <utility>
#include <vector>

namespace metrofit::setup {

DfqPart measurementsDfqPart(const Model& model, const Measurements& meas, const std::string& partNumber) {
  DfqPart part;
  part.number = partNumber;
  part.description = "Metrofit measured features of " + std::to_string(meas.parts.size()) + " part(s)";
  std::vector<DfqCharacteristic> byDimension(model.dimensions.size());
  for (const auto& row : meas.rows) {
    const Dimension& d = model.dimensions[row.dimension];
    byDimension[row.dimension].values.push_back(d.nominal ? *d.nominal + row.deviationMm : row.deviationMm);
  }
  for (std::size_t i = 0; i < model.dimensions.size(); ++i) {
    DfqCharacteristic& c = byDimension[i];
    if (c.values.empty()) continue;
    const Dimension& d = model.dimensions[i];
    const double nominal = d.nominal.value_or(0.0);
    c.number = d.id;
    c.description = d.nominal ? d.id : d.id + " deviation (measured - nominal)";
    c.nominal = nominal;
    if (d.lower < d.upper) {  // a zero-width tolerance is no SPC limit pair
      c.lowerLimit = nominal + d.lower;
      c.upperLimit = nominal + d.upper;
    }
    c.unit = "mm";
    part.characteristics.push_back(std::move(c));
  }
  return part;
}

}  // namespace metrofit::setup
