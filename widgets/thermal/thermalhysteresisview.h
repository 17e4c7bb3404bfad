#pragma once
// Hysteresis view of a thermal log (Abdulshahed 2016, grey neural network thermal model, Fig. 9): the target
// (displacement) against one sensor or against every sensor (small multiples), heating and cooling runs
// coloured as the trend chart's phase bands, and a side table with each sensor's loop area and lag
// (core/thermal/hysteresis.h). Qt Charts stays behind the pimpl.
#include <QWidget>
#include <memory>
#include <string>
#include <vector>

namespace metrofit {
struct ThermalLog;
namespace thermal {
struct ThermalSeries;
struct HysteresisAnalysis;
}  // namespace thermal

class ThermalHysteresisView : public QWidget {
  Q_OBJECT
 public:
  explicit ThermalHysteresisView(QWidget* parent = nullptr);
  ~ThermalHysteresisView() override;

  /// Analyses `target` against `inputs` of `log` and shows the result. Returns false (and shows the
  /// one-line error) when the analysis fails, e.g. for a constant column. Drops a pending analyseLater.
  bool setLog(const ThermalLog& log, const std::string& target, const std::vector<std::string>& inputs);
  /// The same analysis on a worker thread (a long log takes a noticeable part of a second): the view
  /// says it is analysing and shows the result when it is ready (analysisFinished). A later call or
  /// setLog replaces a pending analysis; its result is never shown.
  void analyseLater(const ThermalLog& log, const std::string& target, const std::vector<std::string>& inputs);
  /// An analysis runs on the worker.
  bool isAnalysing() const;
  /// Waits for the pending analysis and shows it now; returns whether the analysis shown worked
  /// (the last one when none was pending).
  bool finishAnalysis();
  /// Shows one sensor (its name) or all of them (an empty name).
  void setSensor(const QString& sensor);
  /// The sensor shown, empty for all.
  QString sensor() const;
  /// The last analysis (empty when none).
  const thermal::HysteresisAnalysis& analysis() const;
  /// Number of charts currently shown (1, or one per sensor).
  int chartCount() const;
  /// The error of the last setLog, empty when it worked.
  QString errorMessage() const;

 signals:
  void sensorChanged(const QString& sensor);
  /// The result of analyseLater is shown; `ok` false: the analysis failed (errorMessage()).
  void analysisFinished(bool ok);

 private:
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
