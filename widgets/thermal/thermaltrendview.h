#pragma once
// Sensor trend chart of a thermal log: temperatures (left axis, degC) and displacement / other
// channels (right axis, in their own unit) against time (h or min), heating and cooling phases
// shaded, channels selectable. Qt Charts stays behind the pimpl: this header is cheap to include.
#include <QWidget>
#include <memory>

namespace metrofit {
struct ThermalLog;

class ThermalTrendView : public QWidget {
  Q_OBJECT
 public:
  explicit ThermalTrendView(QWidget* parent = nullptr);
  ~ThermalTrendView() override;

  /// Shows a log. All channels visible by default (at most 8 temperatures pre-selected).
  void setLog(const ThermalLog& log);
  /// Channel names currently shown.
  QStringList visibleChannels() const;
  /// Shows exactly these channels (unknown names are ignored).
  void setVisibleChannels(const QStringList& names);

 signals:
  void visibleChannelsChanged(const QStringList& names);

 private:
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
