#include "widgets/common/palette.h"

#include <array>

namespace metrofit::palette {

namespace {
constexpr std::array<QRgb, 10> kSeries = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                          0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
}  // namespace

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
