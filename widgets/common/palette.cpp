#include "widgets/common/palette.h"

#include <algorithm>
#include <array>

namespace metrofit::palette {

namespace {
constexpr std::array<QRgb, 10> kSeries = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                          0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
// Temperatures: Tableau 10, then ten further hues that differ from those in hue or lightness.
constexpr std::array<QRgb, 20> kTemperatures = {
    0xd62728, 0x1f77b4, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x17becf, 0x8c564b, 0xe377c2, 0xbcbd22, 0x7f7f7f,
    0x393b79, 0xe7ba52, 0x7b4173, 0x637939, 0xff9896, 0x6baed6, 0xc49c94, 0x74c476, 0xf7b6d2, 0xa55194};
// Displacements (and strains): dark hues, drawn dashed over the temperatures.
constexpr std::array<QRgb, 10> kDisplacements = {0xb8007a, 0x0b3c8c, 0x006d2c, 0xc03000, 0x006d6d,
                                                 0x9a5b00, 0x4b3fa0, 0x000000, 0x5a5a5a, 0x7a0a0a};
constexpr std::array<QRgb, 5> kSpeeds = {0x303030, 0x6a3d9a, 0x005a32, 0x8c2d04, 0x08306b};

template <std::size_t N>
QColor cycled(const std::array<QRgb, N>& colours, int index) {
  const int n = static_cast<int>(N);
  const int i = std::max(0, index);
  const QColor base(colours[static_cast<std::size_t>(i % n)]);
  return i < n ? base : base.darker(100 + 35 * (i / n));
}
}  // namespace

QColor temperatureSeries(int index) {
  return cycled(kTemperatures, index);
}
QColor displacementSeries(int index) {
  return cycled(kDisplacements, index);
}
QColor speedSeries(int index) {
  return cycled(kSpeeds, index);
}

QColor nominal() {
  return QColor(0x6e, 0x6e, 0x6e);
}
QColor measured() {
  return QColor(0x1f, 0x77, 0xb4);
}
QColor measuredSecond() {
  return QColor(0xe6, 0x55, 0x0d);
}
QColor compensated() {
  return QColor(0x2c, 0xa0, 0x2c);
}
QColor predicted() {
  return QColor(0x94, 0x67, 0xbd);
}

QColor modelGnnmci() {
  return QColor(0xd6, 0x27, 0x28);
}
QColor modelGmc() {
  return QColor(0xff, 0x7f, 0x0e);
}
QColor modelMlp() {
  return QColor(0x8c, 0x56, 0x4b);
}

QColor heatingFill() {
  return QColor(0xfb, 0xe0, 0xd2);
}
QColor coolingFill() {
  return QColor(0xd8, 0xe8, 0xf6);
}
QColor heatingLine() {
  return QColor::fromHsv(heatingFill().hsvHue(), 210, 210);
}
QColor coolingLine() {
  return QColor::fromHsv(coolingFill().hsvHue(), 210, 210);
}

QColor controlLimit() {
  return QColor(0xd6, 0x27, 0x28);
}
QColor centreLine() {
  return QColor(0x2c, 0xa0, 0x2c);
}
QColor specLimit() {
  return QColor(0x78, 0x1e, 0x78);
}
QColor histogramBars() {
  return QColor(0x6b, 0xae, 0xd6);
}

QColor before() {
  return QColor(0x9e, 0x9e, 0x9e);
}
QColor after() {
  return QColor(0x21, 0x66, 0xac);
}
QColor outOfTolerance() {
  return QColor(0xd6, 0x27, 0x28);
}
QColor inTolerance() {
  return QColor::fromRgbF(0.20f, 0.63f, 0.17f);
}
QColor toleranceZone() {
  return QColor(0xdf, 0xf1, 0xdc);
}
QColor reference() {
  return QColor(0x20, 0x20, 0x20);
}
QColor grid() {
  return QColor(0xe1, 0xe1, 0xe1);
}
QColor axisText() {
  return QColor(0x50, 0x50, 0x50);
}
QColor goodText() {
  return QColor(0x1b, 0x7a, 0x1b);
}
QColor badText() {
  return QColor(0xb2, 0x18, 0x2b);
}

QColor coldEnd() {
  return QColor::fromRgbF(0.230f, 0.299f, 0.754f);
}
QColor coldLight() {
  return QColor::fromRgbF(0.55f, 0.70f, 0.95f);
}
QColor warmLight() {
  return QColor::fromRgbF(0.98f, 0.62f, 0.45f);
}
QColor warmEnd() {
  return QColor::fromRgbF(0.706f, 0.016f, 0.150f);
}

QColor series(int index) {
  const auto n = static_cast<int>(kSeries.size());
  return QColor(kSeries[static_cast<std::size_t>(((index % n) + n) % n)]);
}

}  // namespace metrofit::palette
