// Every view translated: locale numbers, units on axes and tables that fit, checked without
// translations loaded (the sentences are English, the numbers follow QLocale's default).
#include <QChart>
#include <QHeaderView>
#include <QLocale>
#include <QScrollBar>
#include <QTableWidget>
#include <QTest>

#include <memory>

#include "core/sim/thermal_sim.h"
#include "core/spc/spc.h"
#include "core/thermal/hysteresis.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "qtapp.h"
#include "widgets/diagnose/coretexts.h"
#include "widgets/kinematics/kinematicsviews.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermalhysteresisview.h"
#include "widgets/thermal/thermalmodelcharts.h"

namespace metrofit {
namespace {

/// Sets QLocale's default for one test and restores it.
class LocaleScope {
 public:
  explicit LocaleScope(QLocale::Language language) : saved_(QLocale()) {
    QLocale::setDefault(QLocale(language));
  }
  ~LocaleScope() { QLocale::setDefault(saved_); }

 private:
  QLocale saved_;
};

TEST(I18nViews, InputChannelAxisTitlesCarryTheirUnits) {
  const ThermalChannel feed{"z_speed_mpm", "", {}};
  EXPECT_EQ(channelUnit(feed), QStringLiteral("m/min"));
  EXPECT_EQ(channelAxisTitle(feed), QStringLiteral("feed speed (m/min)"));
  const ThermalChannel spindle{"c_rpm", "rpm", {}};
  EXPECT_EQ(channelAxisTitle(spindle), QStringLiteral("speed (rpm)"));
  const ThermalChannel ambient{"T_amb", "", {}};
  EXPECT_EQ(channelAxisTitle(ambient), QStringLiteral("temperature (°C)"));
  const ThermalChannel strain{"FBG1_ue", "ue", {}};
  EXPECT_EQ(channelAxisTitle(strain), QStringLiteral("strain (µε)"));
  const ThermalChannel disp{"disp_z_um", "um", {}};
  EXPECT_EQ(channelAxisTitle(disp), QStringLiteral("displacement (µm)"));
}

TEST(I18nViews, HysteresisTitleUsesTheLocaleDecimal) {
  const LocaleScope german(QLocale::German);
  const ThermalLog log = simulateThermalTest({});
  const thermal::ThermalSeries series = thermal::selectThermalSeries(log, "disp_z_um", {"T1"});
  const thermal::HysteresisAnalysis analysis = thermal::analyseHysteresis(series);
  HysteresisChartOptions o;
  o.compactTitle = true;
  std::unique_ptr<QChart> chart(makeHysteresisChart(log, series, analysis, 0, o));
  const QString tau = QLocale().toString(analysis.sensors[0].tauMin, 'f', 1);
  ASSERT_TRUE(tau.contains(QLatin1Char(',')));
  EXPECT_EQ(chart->title(), QStringLiteral("T1: lag %1 min").arg(tau));
}

TEST(I18nViews, HysteresisTableFitsWithoutSidewaysScrolling) {
  const LocaleScope polish(QLocale::Polish);
  const ThermalLog log = simulateThermalTest({});
  ThermalHysteresisView view;
  view.resize(1000, 560);  // the tab's size in a 1280 x 800 screenshot
  ASSERT_TRUE(view.setLog(log, "disp_z_um", {"T1", "T2", "T3", "T4"}));
  view.show();
  QCoreApplication::processEvents();
  auto* table = view.findChild<QTableWidget*>(QStringLiteral("hysteresisTable"));
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->horizontalScrollBar()->maximum(), 0);
  int total = 0;
  for (int c = 0; c < table->columnCount(); ++c) {
    EXPECT_GT(table->columnWidth(c), 30) << c;
    total += table->columnWidth(c);
  }
  EXPECT_LE(total, table->viewport()->width());
  // The numbers use the locale's decimal comma and are not elided.
  EXPECT_TRUE(table->item(0, 4)->text().contains(QLatin1Char(',')));
  EXPECT_FALSE(table->horizontalHeaderItem(5)->toolTip().isEmpty());
}

TEST(I18nViews, SpcCompensationIsTheWidgetsSentenceWithLocaleNumbers) {
  const LocaleScope german(QLocale::German);
  // Five subgroups of five, in control, mean 100.0016: the systematic error -0.0016 is significant.
  std::vector<double> values;
  for (int g = 0; g < 5; ++g)
    for (int i = 0; i < 5; ++i) values.push_back(100.0 + 0.002 * ((i * 3 + g) % 5) - 0.0024);
  SpcOptions o;
  o.nominal = 100.0;
  const SpcResult r = analyseSpc(values, o);
  ASSERT_TRUE(r.systematic && r.systematic->significant);
  ASSERT_TRUE(r.decision.apply);
  const QString text = SpcView::compensationText(r);
  EXPECT_TRUE(text.startsWith(QStringLiteral("compensate -0,0016:"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("(k = 2)"))) << text.toStdString();
  EXPECT_FALSE(text.contains(QStringLiteral("0.0"))) << text.toStdString();
  // Core's English reason (JSON / CLI) is unchanged and made from the same phrases.
  EXPECT_EQ(r.decision.reason.rfind("compensate -0.0016", 0), 0u) << r.decision.reason;
  EXPECT_EQ(english(r.decision.reasonParts), r.decision.reason);

  SpcOptions none;
  const SpcResult n = analyseSpc(values, none);
  EXPECT_EQ(SpcView::compensationText(n),
            QStringLiteral("no nominal value given: nothing to compensate against"));

  // Every decision's phrases are in the GUI's list of core texts (so lupdate and the translators see
  // them): in control and significant, not significant, below the smallest correction, out of control.
  std::vector<std::string> formats;
  collectFormats(r.decision.reasonParts, formats);
  collectFormats(n.decision.reasonParts, formats);
  SpcOptions big = o;
  big.minCorrection = 1.0;
  collectFormats(analyseSpc(values, big).decision.reasonParts, formats);
  std::vector<double> flat(25, 100.0);
  for (std::size_t i = 0; i < flat.size(); ++i) flat[i] += 0.001 * static_cast<double>(i % 5) - 0.002;
  collectFormats(analyseSpc(flat, o).decision.reasonParts, formats);
  std::vector<double> shifted = values;
  for (int i = 20; i < 25; ++i) shifted[static_cast<std::size_t>(i)] += 0.05;
  collectFormats(analyseSpc(shifted, o).decision.reasonParts, formats);
  EXPECT_GE(formats.size(), 6u);
  for (const std::string& f : formats) EXPECT_TRUE(isCoreTextSource(f)) << f;
}

TEST(I18nViews, SpcTableHasNoSidewaysScrollBarAndRowsFitTheirText) {
  const LocaleScope polish(QLocale::Polish);
  std::vector<double> values;
  for (int g = 0; g < 5; ++g)
    for (int i = 0; i < 5; ++i) values.push_back(100.0015 + 0.002 * ((i * 3 + g) % 5) - 0.004);
  SpcOptions o;
  o.nominal = 100.0;
  o.lsl = 99.98;
  o.usl = 100.02;
  const SpcResult r = analyseSpc(values, o);
  SpcView view;
  view.resize(1000, 560);
  view.setResult(r, values, QStringLiteral("diameter_mm"), QStringLiteral("mm"));
  view.show();
  QCoreApplication::processEvents();
  QTableWidget* table = view.indexTable();
  EXPECT_EQ(table->horizontalScrollBar()->maximum(), 0);
  EXPECT_EQ(table->horizontalScrollBarPolicy(), Qt::ScrollBarAlwaysOff);
  // Every value fits its cell: the wrapped text's height at the column's width (less the cell's
  // margins) is within the row's height.
  const int width = table->columnWidth(1) - 8;
  ASSERT_GT(width, 100);
  for (int row = 0; row < table->rowCount(); ++row) {
    const QRect need = table->fontMetrics().boundingRect(QRect(0, 0, width, 10000), Qt::TextWordWrap,
                                                         table->item(row, 1)->text());
    EXPECT_LE(need.width(), width) << row << " " << table->item(row, 1)->text().toStdString();
    EXPECT_LE(need.height(), table->rowHeight(row))
        << row << " " << table->item(row, 1)->text().toStdString();
  }
}

}  // namespace
}  // namespace metrofit
