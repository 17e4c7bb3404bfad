#pragma once
// The optimisation curve of the fine matching (the paper's Fig. 6 and 8): the best objective of
// Eq. (8), as an RMS in mm, against the generation, one line per method (SADE, GA-simplex), on a
// logarithmic axis; the least-squares optimum (closed form) as a dashed reference line. Qt Charts
// stays behind the pimpl.
#include <QWidget>
#include <memory>
#include <vector>

class QChart;

namespace metrofit {

class MatchingCurveView : public QWidget {
  Q_OBJECT
 public:
  explicit MatchingCurveView(QWidget* parent = nullptr);
  ~MatchingCurveView() override;

  /// Sets (replaces) the curve of `method`: (generation, best objective in mm) pairs.
  void setCurve(const QString& method, const std::vector<std::pair<double, double>>& points);
  /// The least-squares optimum (mm) as a reference line; <= 0 removes it.
  void setOptimum(double rmseMm);
  void clear();

  /// Number of curves (without the reference line).
  int curveCount() const;
  QStringList curveNames() const;
  QChart* chart() const;

 private:
  void rebuild();
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
