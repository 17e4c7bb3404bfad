#pragma once
// The live convergence chart of the setup correction (setupcharts.h): runs are added and fed with
// trace points while they run (the page posts them from the worker thread in batches), several
// runs stay overlaid to compare methods, the exact optimum is the reference line. Check boxes show
// or hide f2 and f. Qt Charts stays behind the pimpl.
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "widgets/setup/setupcharts.h"

namespace metrofit {

class SetupConvergenceView : public QWidget {
  Q_OBJECT
 public:
  explicit SetupConvergenceView(QWidget* parent = nullptr);
  ~SetupConvergenceView() override;

  /// Starts a new run; returns its index.
  int addRun(const QString& method, std::uint64_t seed);
  /// Appends trace points to run `index` and redraws.
  void appendPoints(int index, const std::vector<SetupTracePoint>& points);
  /// The exact optimum (reference lines); nullopt removes them.
  void setExact(const std::optional<setup::SetupScore>& exact);
  void setBudget(long budget);
  void clearRuns();

  const std::vector<SetupConvergenceRun>& runs() const;
  bool hasExact() const;
  /// Series in the chart (for tests: f1/f2/f per run plus the reference lines).
  int seriesCount() const;
  /// Legend texts of the visible legend markers.
  QStringList legendLabels() const;

 private:
  void rebuild();
  struct Impl;
  std::unique_ptr<Impl> d;
};

}  // namespace metrofit
