#pragma once
// Round numbers for chart axes, magnifications and scale bars: 1, 2 or 5 times a power of ten.
// One place for every chart of the pages and the report, and the plot data of core/study.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace metrofit::ticks {

/// The range of the finite values added; empty (not valid) until one is.
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool valid() const { return lo <= hi; }
  /// Widened by `fraction` of the span on both sides (a unit around a single value); [0, 1] when
  /// nothing was added.
  Range padded(double fraction = 0.05) const {
    if (!valid()) return {0.0, 1.0};
    const double span = hi - lo;
    const double pad = span > 0.0 ? fraction * span : std::max(1e-9, 0.5 * std::abs(lo) + 0.5);
    return {lo - pad, hi + pad};
  }
};

/// The largest 1, 2 or 5 x 10^n that is <= x; 1 when x is not a finite positive number.
double niceFloor(double x);
/// The smallest 1, 2 or 5 x 10^n that is >= x; 1 when x is not a finite positive number.
double niceCeil(double x);
/// A tick step for `span` divided into about `count` intervals: niceCeil(span / count), so that
/// count steps cover the span; 1 when span or count is not positive.
double niceStep(double span, int count);
/// The multiples of niceStep(hi - lo, count) from the first >= lo to the last <= hi.
std::vector<double> tickValues(double lo, double hi, int count);

}  // namespace metrofit::ticks
