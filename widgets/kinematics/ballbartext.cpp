#include "widgets/kinematics/ballbartext.h"

#include <QCoreApplication>

namespace metrofit {
namespace {

struct BallbarText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::BallbarText)
};

/// The axis letter of a name ending in _x / _y, empty otherwise.
QString axisOf(const std::string& name) {
  if (name.size() > 2 && name[name.size() - 2] == '_') {
    if (name.back() == 'x') return QStringLiteral("X");
    if (name.back() == 'y') return QStringLiteral("Y");
  }
  return {};
}

std::string stem(const std::string& name) {
  return axisOf(name).isEmpty() ? name : name.substr(0, name.size() - 2);
}

}  // namespace

QString ballbarCauseName(const std::string& name) {
  const QString axis = axisOf(name);
  const std::string s = stem(name);
  if (s == "backlash") return BallbarText::tr("Backlash %1").arg(axis);
  if (s == "reversal_spike") return BallbarText::tr("Reversal spikes %1").arg(axis);
  if (s == "lateral_play") return BallbarText::tr("Lateral play %1").arg(axis);
  if (s == "straightness") return BallbarText::tr("Straightness %1").arg(axis);
  if (s == "cyclic_error") return BallbarText::tr("Cyclic error %1").arg(axis);
  if (name == "servo_mismatch") return BallbarText::tr("Servo mismatch");
  if (name == "scale_mismatch") return BallbarText::tr("Scale mismatch");
  if (name == "squareness") return BallbarText::tr("Squareness");
  if (name == "unexplained") return BallbarText::tr("Unexplained (RMS)");
  return QString::fromStdString(name);
}

QString ballbarCauseTip(const std::string& name) {
  const QString axis = axisOf(name);
  const std::string s = stem(name);
  if (s == "backlash") {
    return BallbarText::tr(
               "Lost motion of the %1 axis at its reversals: the axis lags half of it behind its "
               "direction of motion")
        .arg(axis);
  }
  if (s == "reversal_spike") {
    return BallbarText::tr(
               "Peak of a short lag of the %1 axis after each reversal, decaying over about 2° of "
               "the path; positive: outwards")
        .arg(axis);
  }
  if (s == "lateral_play") {
    return BallbarText::tr("Sideways step of the %1 carriage when its axis reverses").arg(axis);
  }
  if (s == "straightness") {
    return BallbarText::tr("Bow of the %1 axis across the test diameter (its middle relative to its ends)")
        .arg(axis);
  }
  if (s == "cyclic_error") {
    return BallbarText::tr("Amplitude of the periodic error of the %1 axis with the screw pitch").arg(axis);
  }
  if (name == "servo_mismatch") {
    return BallbarText::tr(
        "Difference of the X and Y following errors at the test's feed; positive: X lags more");
  }
  if (name == "scale_mismatch") {
    return BallbarText::tr("(Scale of X − scale of Y) × radius; positive: X travels further than Y");
  }
  if (name == "squareness") {
    return BallbarText::tr("Squareness error (b − a) × radius: the shear over the test radius");
  }
  if (name == "unexplained") {
    return BallbarText::tr("RMS of what the causes leave: noise and errors not in the list");
  }
  return {};
}

}  // namespace metrofit
