// Tests of the thermal trend chart: phase detection and decimation (trend_analysis.h) on profiles
// with known answers, the chart's axes (thermalcharts.h), and ThermalTrendView rendered offscreen
// (series and band colours present in the pixels, hiding a channel removes its colour).
// Grabbed images are saved into $METROFIT_TEST_OUT for a look.
#include <gtest/gtest.h>

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QDir>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QImage>
#include <QLegend>
#include <QLegendMarker>
#include <QPainter>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStyleOptionViewItem>
#include <QTest>
#include <QTreeWidget>
#include <QValueAxis>
#include <QXYSeries>

#include <cmath>
#include <memory>
#include <random>

#include "core/common/error.h"
#include "core/study/trend_analysis.h"
#include "core/thermal/thermal_log.h"
#include "qtapp.h"
#include "widgets/thermal/thermalcharts.h"
#include "widgets/thermal/thermaltrendview.h"

namespace metrofit {
namespace {

QString outputDir() {
  const QString dir = qEnvironmentVariable("METROFIT_TEST_OUT", QDir::tempPath());
  QDir().mkpath(dir);
  return dir;
}

constexpr double kSwitchMin = 150.0;  ///< heating ends, cooling starts

/// Heating (first-order rise) until kSwitchMin, then cooling (first-order decay), in [0, 1].
double heatProfile(double t) {
  const double top = 1.0 - std::exp(-kSwitchMin / 50.0);
  return t < kSwitchMin ? 1.0 - std::exp(-t / 50.0) : top * std::exp(-(t - kSwitchMin) / 60.0);
}

/// `rows` rows one minute apart: temperatures T1..T<temperatures> rising then falling by
/// 4, 6, 8, ... degC, a displacement disp_z_um = -15 um * profile. Optional Gaussian noise.
ThermalLog makeLog(std::size_t rows = 300, int temperatures = 4, double noise = 0.0, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise > 0.0 ? noise : 1.0);
  ThermalLog log;
  log.source = "memory";
  log.timeColumn = "time_min";
  for (std::size_t i = 0; i < rows; ++i) {
    log.timeMin.push_back(static_cast<double>(i));
  }
  for (int k = 0; k < temperatures; ++k) {
    ThermalChannel c;
    c.name = "T" + std::to_string(k + 1);
    for (double t : log.timeMin) {
      c.values.push_back(20.0 + (4.0 + 2.0 * k) * heatProfile(t) + (noise > 0.0 ? gauss(rng) : 0.0));
    }
    log.channels.push_back(c);
  }
  ThermalChannel disp;
  disp.name = "disp_z_um";
  disp.unit = "um";
  for (double t : log.timeMin) {
    disp.values.push_back(-15.0 * heatProfile(t));
  }
  log.channels.push_back(disp);
  return log;
}

/// Pixels whose colour is within `tolerance` of `c` in every channel.
int countColour(const QImage& image, const QColor& c, int tolerance = 40) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  int n = 0;
  for (int y = 0; y < img.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(img.constScanLine(y));
    for (int x = 0; x < img.width(); ++x) {
      if (std::abs(qRed(line[x]) - c.red()) <= tolerance &&
          std::abs(qGreen(line[x]) - c.green()) <= tolerance &&
          std::abs(qBlue(line[x]) - c.blue()) <= tolerance) {
        ++n;
      }
    }
  }
  return n;
}

int distinctColours(const QImage& image) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  QSet<QRgb> colours;
  for (int y = 0; y < img.height(); y += 2) {
    const auto* line = reinterpret_cast<const QRgb*>(img.constScanLine(y));
    for (int x = 0; x < img.width(); x += 2) {
      colours.insert(line[x]);
    }
  }
  return static_cast<int>(colours.size());
}

// ---- phase detection and decimation ----

TEST(TrendAnalysis, LocalSlopeOfALineIsItsSlope) {
  std::vector<double> t, v;
  for (int i = 0; i < 50; ++i) {
    t.push_back(i * 0.5 + (i % 3) * 0.1);  // uneven spacing
    v.push_back(3.0 - 0.25 * t.back());
  }
  for (double s : localSlope(t, v, 4.0)) {
    EXPECT_NEAR(s, -0.25, 1e-9);
  }
}

TEST(TrendAnalysis, SlopePhasesOfHeatingThenCooling) {
  const ThermalLog log = makeLog();
  const PhaseDetection detection = detectThermalPhases(log);
  EXPECT_EQ(detection.source, PhaseSource::TemperatureSlope);
  ASSERT_EQ(detection.phases.size(), 2u);
  EXPECT_EQ(detection.phases[0].kind, ThermalPhaseKind::Heating);
  EXPECT_NEAR(detection.phases[0].startMin, 0.0, 1.0);
  EXPECT_NEAR(detection.phases[0].endMin, kSwitchMin, 4.0);
  EXPECT_EQ(detection.phases[1].kind, ThermalPhaseKind::Cooling);
  EXPECT_NEAR(detection.phases[1].startMin, kSwitchMin, 4.0);
  EXPECT_GT(detection.phases[1].endMin, 250.0);
}

TEST(TrendAnalysis, SlopePhasesSurviveSensorNoise) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const ThermalLog log = makeLog(300, 4, 0.05, seed);
    const PhaseDetection detection = detectThermalPhases(log);
    ASSERT_EQ(detection.phases.size(), 2u) << "seed " << seed;
    EXPECT_EQ(detection.phases[0].kind, ThermalPhaseKind::Heating);
    EXPECT_NEAR(detection.phases[0].startMin, 0.0, 2.0);
    EXPECT_NEAR(detection.phases[0].endMin, kSwitchMin, 6.0);
    EXPECT_EQ(detection.phases[1].kind, ThermalPhaseKind::Cooling);
    EXPECT_NEAR(detection.phases[1].startMin, kSwitchMin, 6.0);
  }
}

TEST(TrendAnalysis, NoPhasesInAFlatNoisyLog) {
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, 0.02);
  std::vector<double> t, v;
  for (int i = 0; i < 400; ++i) {
    t.push_back(i);
    v.push_back(21.0 + gauss(rng));
  }
  EXPECT_TRUE(phasesFromSlope(t, v).empty());
}

TEST(TrendAnalysis, SpeedPhasesFollowTheSpindle) {
  // Idle 0-10 min, 1000 rpm to 100, stop to 200, 2000 rpm to 250 with a 1-min dropout at 220,
  // stop to the end (299).
  std::vector<double> t, speed;
  for (int i = 0; i < 300; ++i) {
    t.push_back(i);
    const bool running = (i >= 10 && i < 100) || (i >= 200 && i < 250 && i != 220);
    speed.push_back(running ? (i < 100 ? 1000.0 : 2000.0) : 0.0);
  }
  const std::vector<ThermalPhase> phases = phasesFromSpeed(t, speed);
  ASSERT_EQ(phases.size(), 4u);
  const ThermalPhaseKind H = ThermalPhaseKind::Heating;
  const ThermalPhaseKind C = ThermalPhaseKind::Cooling;
  const double expected[4][2] = {{9.5, 99.5}, {99.5, 199.5}, {199.5, 249.5}, {249.5, 299.0}};
  const ThermalPhaseKind kinds[4] = {H, C, H, C};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(phases[k].kind, kinds[k]) << k;
    EXPECT_NEAR(phases[k].startMin, expected[k][0], 1e-9) << k;
    EXPECT_NEAR(phases[k].endMin, expected[k][1], 1e-9) << k;
  }
  EXPECT_TRUE(phasesFromSpeed(t, std::vector<double>(t.size(), 0.0)).empty());
}

TEST(TrendAnalysis, SpeedChannelTakesPrecedence) {
  ThermalLog log = makeLog();
  ThermalChannel rpm;
  rpm.name = "spindle_rpm";
  rpm.unit = "rpm";
  for (double t : log.timeMin) {
    rpm.values.push_back(t >= 20.0 && t < 120.0 ? 3000.0 : 0.0);
  }
  log.channels.push_back(rpm);
  const PhaseDetection detection = detectThermalPhases(log);
  EXPECT_EQ(detection.source, PhaseSource::Speed);
  EXPECT_EQ(detection.channel, "spindle_rpm");
  ASSERT_EQ(detection.phases.size(), 2u);
  EXPECT_NEAR(detection.phases[0].startMin, 19.5, 1e-9);
  EXPECT_NEAR(detection.phases[0].endMin, 119.5, 1e-9);
}

TEST(TrendAnalysis, InvalidOptionsAreRejected) {
  PhaseOptions options;
  options.smoothingFraction = 0.0;
  std::string why;
  EXPECT_FALSE(options.isValid(&why));
  EXPECT_NE(why.find("smoothingFraction"), std::string::npos);
  EXPECT_THROW(detectThermalPhases(makeLog(), options), OptionsError);
  EXPECT_TRUE(PhaseOptions{}.isValid(nullptr));
}

TEST(TrendAnalysis, DecimationKeepsExtremesAndOrder) {
  std::vector<double> t, v;
  for (int i = 0; i < 100000; ++i) {
    t.push_back(i * 0.01);
    v.push_back(std::sin(i * 0.001));
  }
  v[43210] = 5.0;   // a one-sample spike
  v[77777] = -4.0;  // a one-sample dip
  const std::vector<std::size_t> rows = decimateMinMax(t, v, 2000);
  EXPECT_LE(rows.size(), 2000u);
  EXPECT_GT(rows.size(), 1000u);
  EXPECT_EQ(rows.front(), 0u);
  EXPECT_EQ(rows.back(), 99999u);
  EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end()));
  EXPECT_EQ(std::adjacent_find(rows.begin(), rows.end()), rows.end());
  EXPECT_NE(std::find(rows.begin(), rows.end(), 43210u), rows.end());
  EXPECT_NE(std::find(rows.begin(), rows.end(), 77777u), rows.end());
  // Short series are kept whole.
  EXPECT_EQ(decimateMinMax({0, 1, 2}, {5, 6, 7}, 2000).size(), 3u);
}

// ---- the chart ----

TEST(ThermalCharts, AxesTitlesAndUnits) {
  const ThermalLog log = makeLog();  // 299 min: hours
  std::unique_ptr<QChart> chart(makeThermalTrendChart(log, defaultThermalChannels(log)));
  QStringList titles;
  for (QAbstractAxis* axis : chart->axes()) {
    if (axis->isVisible()) {
      titles << axis->titleText();
    }
  }
  EXPECT_TRUE(titles.contains(QStringLiteral("time (h)"))) << titles.join('|').toStdString();
  EXPECT_TRUE(titles.contains(QStringLiteral("temperature (°C)"))) << titles.join('|').toStdString();
  EXPECT_TRUE(titles.contains(QStringLiteral("displacement (µm)"))) << titles.join('|').toStdString();
  // Temperatures on the left, displacement on the right.
  for (QAbstractAxis* axis : chart->axes(Qt::Vertical)) {
    if (axis->titleText().startsWith(QStringLiteral("temperature"))) {
      EXPECT_EQ(axis->alignment(), Qt::AlignLeft);
    }
    if (axis->titleText().startsWith(QStringLiteral("displacement"))) {
      EXPECT_EQ(axis->alignment(), Qt::AlignRight);
    }
  }
  // Five channel series and two phase bands.
  EXPECT_EQ(chart->series().size(), 7);

  const ThermalLog shortLog = makeLog(120);  // 119 min: minutes
  std::unique_ptr<QChart> shortChart(makeThermalTrendChart(shortLog, {QStringLiteral("T1")}));
  bool minutes = false;
  for (QAbstractAxis* axis : shortChart->axes(Qt::Horizontal)) {
    minutes = minutes || axis->titleText() == QStringLiteral("time (min)");
  }
  EXPECT_TRUE(minutes);
}

TEST(ThermalCharts, LongSeriesAreDecimated) {
  const ThermalLog log = makeLog(20000);
  ThermalChartOptions options;
  options.maxPointsPerSeries = 2000;
  std::unique_ptr<QChart> chart(makeThermalTrendChart(log, {QStringLiteral("T1")}, options));
  bool found = false;
  for (QAbstractSeries* s : chart->series()) {
    if (s->objectName() == QStringLiteral("T1")) {
      EXPECT_EQ(s->name(), QStringLiteral("T1 (°C)"));  // the legend names the unit
      found = true;
      const int n = static_cast<int>(static_cast<QXYSeries*>(s)->count());
      EXPECT_LE(n, 2000);
      EXPECT_GE(n, 1000);
    }
  }
  EXPECT_TRUE(found);
}

TEST(ThermalCharts, DefaultSelectionCapsTemperaturesAtEight) {
  const ThermalLog log = makeLog(50, 10);
  const QStringList names = defaultThermalChannels(log);
  EXPECT_EQ(names.size(), 9);  // T1..T8 + disp_z_um
  EXPECT_TRUE(names.contains(QStringLiteral("T8")));
  EXPECT_FALSE(names.contains(QStringLiteral("T9")));
  EXPECT_TRUE(names.contains(QStringLiteral("disp_z_um")));
}

// ---- the view ----

class ThermalTrendViewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    log_ = makeLog();
    view_ = std::make_unique<ThermalTrendView>();
    view_->resize(1000, 600);
    view_->setLog(log_);
    view_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view_.get()));
    chartView_ = view_->findChild<QChartView*>(QStringLiteral("thermalTrendChart"));
    ASSERT_NE(chartView_, nullptr);
  }

  QImage grabChart() {
    QApplication::processEvents();
    return chartView_->grab().toImage();
  }

  QColor colourOf(const char* channel) const { return thermalChannelColor(log_, log_.indexOf(channel)); }

  ThermalLog log_;
  std::unique_ptr<ThermalTrendView> view_;
  QChartView* chartView_ = nullptr;
};

TEST_F(ThermalTrendViewTest, DrawsSeriesAndPhaseBands) {
  EXPECT_EQ(view_->visibleChannels(), (QStringList{"T1", "T2", "T3", "T4", "disp_z_um"}));
  const QImage image = grabChart();
  image.save(QDir(outputDir()).filePath(QStringLiteral("thermaltrendview.png")));
  view_->grab().save(QDir(outputDir()).filePath(QStringLiteral("thermaltrendview_full.png")));

  EXPECT_GT(distinctColours(image), 50);
  EXPECT_GT(countColour(image, colourOf("T1")), 100);
  EXPECT_GT(countColour(image, colourOf("T4")), 100);
  EXPECT_GT(countColour(image, colourOf("disp_z_um")), 50);
  // The bands fill a large part of the plot: at least 5 % of the chart each.
  const int area = image.width() * image.height();
  EXPECT_GT(countColour(image, thermalPhaseColor(ThermalPhaseKind::Heating), 3), area / 20);
  EXPECT_GT(countColour(image, thermalPhaseColor(ThermalPhaseKind::Cooling), 3), area / 20);
}

TEST_F(ThermalTrendViewTest, HidingAChannelRemovesItsColour) {
  const QColor t1 = colourOf("T1");
  ASSERT_GT(countColour(grabChart(), t1), 100);

  QSignalSpy spy(view_.get(), &ThermalTrendView::visibleChannelsChanged);
  view_->setVisibleChannels({"T2", "T3", "T4", "disp_z_um", "no_such_channel"});
  EXPECT_EQ(spy.count(), 1);
  EXPECT_EQ(view_->visibleChannels(), (QStringList{"T2", "T3", "T4", "disp_z_um"}));
  const QImage hidden = grabChart();
  hidden.save(QDir(outputDir()).filePath(QStringLiteral("thermaltrendview_without_T1.png")));
  EXPECT_EQ(countColour(hidden, t1, 20), 0);
  EXPECT_GT(countColour(hidden, colourOf("T2")), 100);

  // The same selection again changes nothing.
  view_->setVisibleChannels({"T2", "T3", "T4", "disp_z_um"});
  EXPECT_EQ(spy.count(), 1);

  // Ticking T1 in the channel tree brings it back: group "temperatures (°C)", then "displacements (µm)".
  auto* tree = view_->findChild<QTreeWidget*>(QStringLiteral("thermalTrendChannels"));
  ASSERT_NE(tree, nullptr);
  ASSERT_EQ(tree->topLevelItemCount(), 2);
  EXPECT_EQ(tree->topLevelItem(0)->text(0), QStringLiteral("temperatures (°C)"));
  EXPECT_EQ(tree->topLevelItem(1)->text(0), QStringLiteral("displacements (µm)"));
  ASSERT_EQ(tree->topLevelItem(0)->childCount(), 4);
  EXPECT_EQ(tree->topLevelItem(0)->checkState(0), Qt::PartiallyChecked);
  tree->topLevelItem(0)->child(0)->setCheckState(0, Qt::Checked);
  EXPECT_EQ(spy.count(), 2);
  EXPECT_TRUE(view_->visibleChannels().contains(QStringLiteral("T1")));
  EXPECT_GT(countColour(grabChart(), t1), 100);
  EXPECT_EQ(tree->topLevelItem(0)->checkState(0), Qt::Checked);

  // The group's box hides and shows all of the group in one step.
  tree->topLevelItem(0)->setCheckState(0, Qt::Unchecked);
  EXPECT_EQ(spy.count(), 3);
  EXPECT_EQ(view_->visibleChannels(), QStringList{"disp_z_um"});
  const QImage noTemperatures = grabChart();
  EXPECT_EQ(countColour(noTemperatures, t1, 20), 0);
  EXPECT_EQ(countColour(noTemperatures, colourOf("T4"), 20), 0);
  EXPECT_GT(countColour(noTemperatures, colourOf("disp_z_um")), 50);
  tree->topLevelItem(0)->setCheckState(0, Qt::Checked);
  EXPECT_EQ(view_->visibleChannels(), (QStringList{"T1", "T2", "T3", "T4", "disp_z_um"}));
}

TEST_F(ThermalTrendViewTest, OnlyDisplacementMovesItToTheLeftAxis) {
  view_->setVisibleChannels({"disp_z_um"});
  const QImage image = grabChart();
  EXPECT_EQ(countColour(image, colourOf("T1")), 0);
  EXPECT_GT(countColour(image, colourOf("disp_z_um")), 50);
  const QList<QAbstractAxis*> left = chartView_->chart()->axes(Qt::Vertical);
  bool displacementLeft = false;
  for (QAbstractAxis* axis : left) {
    displacementLeft = displacementLeft || (axis->isVisible() && axis->alignment() == Qt::AlignLeft &&
                                            axis->titleText() == QStringLiteral("displacement (µm)"));
  }
  EXPECT_TRUE(displacementLeft);
}

// The real CAIVIAC spindle log the demo bundles: speed-based phases and a readable chart.
TEST(ThermalTrendViewReal, CaiviacSpindleLog) {
  const QString path = QDir(qEnvironmentVariable("METROFIT_SOURCE_DIR"))
                           .filePath(QStringLiteral("resources/demo/data/thermal_caiviac.csv"));
  ASSERT_TRUE(QFileInfo::exists(path)) << "the demo bundles the real log: " << path.toStdString();
  const ThermalLog log = readThermalLog(path.toStdString());
  const PhaseDetection detection = detectThermalPhases(log);
  EXPECT_EQ(detection.source, PhaseSource::Speed);
  // Five 4 h heat / 4 h cool cycles, then a 6 h speed spectrum and a short stop: 6 + 6 phases.
  ASSERT_EQ(detection.phases.size(), 12u);
  EXPECT_EQ(detection.phases.front().kind, ThermalPhaseKind::Heating);
  EXPECT_NEAR(detection.phases.front().startMin / 60.0, 0.13, 0.01);
  EXPECT_NEAR(detection.phases[1].startMin / 60.0, 4.13, 0.01);

  ThermalTrendView view;
  view.resize(1200, 650);
  view.setLog(log);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  QApplication::processEvents();
  const QImage image = view.grab().toImage();
  image.save(QDir(outputDir()).filePath(QStringLiteral("thermaltrendview_caiviac.png")));
  EXPECT_GT(countColour(image, thermalChannelColor(log, log.indexOf("t1_degC"))), 100);

  // Grouped: temperatures (°C), displacements (µm), speed (rpm); 22 distinct channel colours
  // within the groups, every shown channel's colour in the pixels.
  const std::vector<ThermalChannelGroup> groups = thermalChannelGroups(log);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].title, QStringLiteral("temperatures (°C)"));
  EXPECT_EQ(groups[0].channels.size(), 16u);
  EXPECT_EQ(groups[1].title, QStringLiteral("displacements (µm)"));
  EXPECT_EQ(groups[1].channels.size(), 5u);
  EXPECT_EQ(groups[2].title, QStringLiteral("speed (rpm)"));
  for (const ThermalChannelGroup& g : groups) {
    for (std::size_t a = 0; a < g.channels.size(); ++a) {
      for (std::size_t b = a + 1; b < g.channels.size(); ++b) {
        const QColor ca = thermalChannelColor(log, g.channels[a]),
                     cb = thermalChannelColor(log, g.channels[b]);
        const int distance = std::abs(ca.red() - cb.red()) + std::abs(ca.green() - cb.green()) +
                             std::abs(ca.blue() - cb.blue());
        EXPECT_GT(distance, 60) << log.channels[g.channels[a]].name << " and "
                                << log.channels[g.channels[b]].name
                                << " look alike: " << ca.name().toStdString() << " "
                                << cb.name().toStdString();
      }
    }
  }
  auto* chart = view.findChild<QChartView*>(QStringLiteral("thermalTrendChart"));
  ASSERT_NE(chart, nullptr);
  const QImage chartImage = chart->grab().toImage();  // without the swatches of the channel list
  for (const QString& name : view.visibleChannels()) {
    EXPECT_GT(countColour(chartImage, thermalChannelColor(log, log.indexOf(name.toStdString())), 20), 30)
        << name.toStdString() << " is not to be seen";
  }
  // The channel tree is the legend: group titles name the units, no entry is cut.
  auto* tree = view.findChild<QTreeWidget*>(QStringLiteral("thermalTrendChannels"));
  ASSERT_NE(tree, nullptr);
  ASSERT_EQ(tree->topLevelItemCount(), 3);
  QStyleOptionViewItem option;
  option.initFrom(tree);
  option.decorationSize = tree->iconSize();
  QAbstractItemModel* model = tree->model();
  int entries = 0;
  for (int g = 0; g < model->rowCount(); ++g) {
    const QModelIndex group = model->index(g, 0);
    QList<QModelIndex> indexes{group};
    for (int i = 0; i < model->rowCount(group); ++i) indexes << model->index(i, 0, group);
    for (const QModelIndex& index : indexes) {
      const QRect rect = tree->visualRect(index);
      const int needed = tree->itemDelegate()->sizeHint(option, index).width();
      EXPECT_GE(rect.width(), needed)
          << index.data().toString().toStdString() << " is cut in the channel list";
      EXPECT_LE(rect.left() + needed, tree->viewport()->width()) << index.data().toString().toStdString();
      ++entries;
    }
  }
  EXPECT_EQ(entries, 25);
  // Unticking a displacement channel takes its colour out of the chart.
  const QColor ch1 = thermalChannelColor(log, log.indexOf("ch1_um"));
  view.setVisibleChannels(
      QStringList(view.visibleChannels()).filter(QRegularExpression(QStringLiteral("^(?!ch1_um$)"))));
  QApplication::processEvents();
  EXPECT_EQ(countColour(chart->grab().toImage(), ch1, 20), 0);
  EXPECT_GT(countColour(image, thermalPhaseColor(ThermalPhaseKind::Cooling), 3),
            image.width() * image.height() / 20);
}

}  // namespace
}  // namespace metrofit

namespace metrofit {
namespace {

/// Texts of a laid-out chart that Qt Charts cut to fit ("..." at the end).
QStringList elidedTexts(QGraphicsScene& scene) {
  QStringList cut;
  for (QGraphicsItem* item : scene.items()) {
    if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text && text->isVisible()) {
      const QString plain = text->toPlainText();
      if (plain.endsWith(QStringLiteral("...")) || plain.endsWith(QChar(0x2026))) cut << plain;
    }
  }
  return cut;
}

// The report's trend chart of the real CAIVIAC log (as thermalsection.cpp makes it, laid out at the
// report's design width): legend grouped like the axes, every channel entry names its unit,
// nothing elided.
TEST(ThermalChartsReport, CaiviacLegendGroupedWithUnitsNotElided) {
  const QString path = QDir(qEnvironmentVariable("METROFIT_SOURCE_DIR"))
                           .filePath(QStringLiteral("resources/demo/data/thermal_caiviac.csv"));
  const ThermalLog log = readThermalLog(path.toStdString());
  ThermalChartOptions options;
  options.channelLegend = true;
  QGraphicsScene scene;
  QChart* chart = makeThermalTrendChart(log, defaultThermalChannels(log), options);
  scene.addItem(chart);
  chart->resize(760.0, 760.0 * 108.0 / 180.0);
  chart->layout()->activate();
  QApplication::processEvents();

  QStringList names;
  for (QLegendMarker* marker : chart->legend()->markers()) {
    if (marker->isVisible() && marker->type() == QLegendMarker::LegendMarkerTypeXY) names << marker->label();
  }
  ASSERT_EQ(names.size(), 14);  // 8 of 16 temperatures, 5 displacements, the speed
  for (int i = 0; i < names.size(); ++i) {
    const QString unit = i < 8    ? QStringLiteral("(°C)")
                         : i < 13 ? QStringLiteral("(µm)")
                                  : QStringLiteral("(rpm)");
    EXPECT_TRUE(names[i].endsWith(unit)) << i << ": " << names[i].toStdString();
  }
  EXPECT_EQ(names.front(), QStringLiteral("t1 (°C)"));
  EXPECT_EQ(names[8], QStringLiteral("ch1 (µm)"));
  EXPECT_EQ(names.back(), QStringLiteral("spindle (rpm)"));
  EXPECT_TRUE(elidedTexts(scene).isEmpty()) << elidedTexts(scene).join(QStringLiteral(" | ")).toStdString();

  QImage image(760, 456, QImage::Format_ARGB32);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    scene.render(&painter, QRectF(image.rect()), chart->sceneBoundingRect());
  }
  image.save(QDir(outputDir()).filePath(QStringLiteral("thermaltrend_report_caiviac.png")));
  EXPECT_GT(countColour(image, thermalChannelColor(log, log.indexOf("ch1_um")), 20), 30);

  // The check sees elision: the same chart squeezed to a third of the width cuts its legend.
  chart->resize(250.0, 456.0);
  chart->layout()->activate();
  EXPECT_FALSE(elidedTexts(scene).isEmpty());
}

}  // namespace
}  // namespace metrofit
