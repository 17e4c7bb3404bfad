// QIF 3 Results files (core/io/qif.h), their CMM report (qifCmmReport) and probe points
// (core/matching/qif_points.h), against the public samples in ../shared/data/real/cmm-qif-samples. The
// expected values are the hand-checked facts of that folder's README (read from the XML by a person),
// typed in here, not computed by the reader; malformed documents are written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/file_io.h"
#include "core/io/qif.h"
#include "core/matching/qif_points.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string sample(const std::string& name) {
  return test::realData("cmm-qif-samples/" + name).string();
}

const QifCharacteristicMeasurement* measurementOf(const QifFile& f, std::size_t part, const std::string& name,
                                                  const std::string& feature = {}) {
  for (const QifCharacteristicMeasurement& m : f.parts.at(part).characteristics) {
    if (f.characteristics[m.characteristic].name != name) continue;
    if (feature.empty()) return &m;
    for (const std::size_t k : m.measured)
      if (f.features[f.parts[part].features[k].feature].name == feature) return &m;
  }
  return nullptr;
}

/// 2 |d - (d.n) n| with d = actual - nominal, n the unit nominal direction (README fact 2).
double diametralPosition(const Eigen::Vector3d& nominal, const Eigen::Vector3d& actual,
                         const Eigen::Vector3d& dir) {
  const Eigen::Vector3d n = dir.normalized();
  const Eigen::Vector3d d = actual - nominal;
  return 2.0 * (d - d.dot(n) * n).norm();
}

void expectVector(const Eigen::Vector3d& v, double x, double y, double z) {
  EXPECT_EQ(v.x(), x);
  EXPECT_EQ(v.y(), y);
  EXPECT_EQ(v.z(), z);
}

TEST(Qif, ResultsSampleHolesDistanceAndProfiles) {
  const std::string path = sample("QIF_Results_Sample.QIF");
  METROFIT_REQUIRE_PATH(path);
  const QifFile f = readQifFile(path);
  EXPECT_EQ(f.linearUnit, "mm");
  ASSERT_EQ(f.features.size(), 6u);
  ASSERT_EQ(f.characteristics.size(), 11u);
  ASSERT_EQ(f.parts.size(), 1u);
  EXPECT_EQ(f.parts[0].resultsId, 89);
  EXPECT_EQ(f.parts[0].status, "FAIL");
  EXPECT_EQ(f.parts[0].characteristics.size(), 13u);
  EXPECT_EQ(f.parts[0].features.size(), 6u);

  // Fact 1: HOLE1.
  const auto hole1 = f.feature("HOLE1");
  ASSERT_TRUE(hole1);
  EXPECT_EQ(f.features[*hole1].type, "Circle");
  EXPECT_EQ(f.features[*hole1].internalExternal, "INTERNAL");
  expectVector(*f.features[*hole1].location, 2433.974609375, 800.617431640625, 890.049621582031);
  EXPECT_EQ(*f.features[*hole1].diameter, 10.0);
  const QifFeatureMeasurement* m1 = f.measurement(0, *hole1);
  ASSERT_NE(m1, nullptr);
  expectVector(*m1->location, 2434.01, 801.52505599193, 889.98);
  EXPECT_EQ(*m1->diameter, 9.499476);
  const QifCharacteristicMeasurement* dia6 = measurementOf(f, 0, "6");
  ASSERT_NE(dia6, nullptr);
  EXPECT_EQ(*dia6->value, 9.499476);
  EXPECT_EQ(dia6->status, "FAIL");
  const QifCharacteristic& c6 = f.characteristics[dia6->characteristic];
  EXPECT_EQ(c6.type, "Diameter");
  EXPECT_EQ(*c6.nominalValue(f.features), 10.0);
  EXPECT_EQ(*c6.lowerLimit(f.features), -0.4);
  EXPECT_EQ(*c6.upperLimit(f.features), 0.4);

  // Fact 2: HOLE1 position 0.897298445619006 PASS, reproduced from the read nominal, actual and normal.
  const QifCharacteristicMeasurement* pos7 = measurementOf(f, 0, "7");
  ASSERT_NE(pos7, nullptr);
  EXPECT_EQ(*pos7->value, 0.897298445619006);
  EXPECT_EQ(pos7->status, "PASS");
  ASSERT_EQ(pos7->measured.size(), 1u);
  EXPECT_EQ(f.parts[0].features[pos7->measured[0]].feature, *hole1);
  EXPECT_NEAR(diametralPosition(*f.features[*hole1].location, *m1->location, *f.features[*hole1].direction),
              0.897298445619006, 1e-12);
  const QifCharacteristic& c7 = f.characteristics[pos7->characteristic];
  EXPECT_EQ(*c7.zone, 1.0);
  EXPECT_EQ(*c7.lowerLimit(f.features), 0.0);
  EXPECT_EQ(*c7.upperLimit(f.features), 1.0);

  // Fact 3: HOLE2, limits 9.6-10.4 as absolute limits (DefinedAsLimit true) around the nominal Ø10.
  const auto hole2 = f.feature("HOLE2");
  ASSERT_TRUE(hole2);
  expectVector(*f.features[*hole2].location, 2496.25146484375, 780.842590332031, 938.272277832031);
  expectVector(*f.measurement(0, *hole2)->location, 2496.39, 781.751759542342, 938.09);
  const QifCharacteristicMeasurement* dia8 = measurementOf(f, 0, "8");
  ASSERT_NE(dia8, nullptr);
  EXPECT_NEAR(*dia8->value, 10.199988, 1e-12);
  EXPECT_EQ(dia8->status, "PASS");
  const QifCharacteristic& c8 = f.characteristics[dia8->characteristic];
  EXPECT_TRUE(c8.definedAsLimit);
  EXPECT_EQ(*c8.minValue, 9.6);
  EXPECT_EQ(*c8.maxValue, 10.4);
  EXPECT_NEAR(*c8.lowerLimit(f.features), -0.4, 1e-12);
  EXPECT_NEAR(*c8.upperLimit(f.features), 0.4, 1e-12);
  const QifCharacteristicMeasurement* pos9 = measurementOf(f, 0, "9");
  ASSERT_NE(pos9, nullptr);
  EXPECT_EQ(*pos9->value, 1.137681133150282);
  EXPECT_EQ(pos9->status, "FAIL");

  // Fact 4: DIST1 = the distance between the actual centres; its nominal that between the nominal ones.
  const QifCharacteristicMeasurement* dist = measurementOf(f, 0, "DIST1");
  ASSERT_NE(dist, nullptr);
  EXPECT_EQ(*dist->value, 81.220808617516994);
  const QifCharacteristic& cd = f.characteristics[dist->characteristic];
  EXPECT_EQ(cd.type, "DistanceBetween");
  EXPECT_EQ(*cd.target, 81.208839738425993);
  EXPECT_EQ(*cd.lowerLimit(f.features), -0.5);
  EXPECT_EQ(*cd.upperLimit(f.features), 0.5);
  ASSERT_EQ(dist->measured.size(), 2u);
  EXPECT_NEAR((*f.measurement(0, *hole2)->location - *m1->location).norm(), 81.220808617516994, 1e-9);
  EXPECT_NEAR((*f.features[*hole2].location - *f.features[*hole1].location).norm(), 81.208839738425993, 1e-9);

  // Fact 5: SURF2 profile zone 1.5 with OuterDisposition 1 = +1.0 / -0.5; TRIM1 zone 4 = +-2.
  const QifCharacteristicMeasurement* prof4 = measurementOf(f, 0, "4");
  ASSERT_NE(prof4, nullptr);
  EXPECT_EQ(*prof4->value, -0.886195693015347);
  EXPECT_EQ(prof4->status, "FAIL");
  const QifCharacteristic& c4 = f.characteristics[prof4->characteristic];
  EXPECT_EQ(*c4.lowerLimit(f.features), -0.5);
  EXPECT_EQ(*c4.upperLimit(f.features), 1.0);
  const auto surf2 = f.feature("SURF2");
  const Eigen::Vector3d d2 = *f.measurement(0, *surf2)->location - *f.features[*surf2].location;
  EXPECT_NEAR(d2.dot(f.features[*surf2].direction->normalized()), -0.886195693015347, 1e-9);
  const QifCharacteristicMeasurement* prof5 = measurementOf(f, 0, "5");
  ASSERT_NE(prof5, nullptr);
  EXPECT_EQ(*prof5->value, -0.020323885079998);
  EXPECT_EQ(prof5->status, "PASS");
  EXPECT_EQ(*f.characteristics[prof5->characteristic].lowerLimit(f.features), -2.0);
  EXPECT_EQ(*f.characteristics[prof5->characteristic].upperLimit(f.features), 2.0);
}

TEST(Qif, SheetMetalSixParts) {
  const std::string path = sample("SheetMetal_QIF_Results_6_samples.QIF");
  METROFIT_REQUIRE_PATH(path);
  const QifFile f = readQifFile(path);
  EXPECT_EQ(f.features.size(), 21u);
  EXPECT_EQ(f.characteristics.size(), 21u);
  ASSERT_EQ(f.parts.size(), 6u);
  const std::vector<std::string> serials{"SN5802801", "SN5802802", "SN5802803",
                                         "SN5802804", "SN5802805", "SN5802806"};
  const std::vector<std::string> statuses{"PASS", "FAIL", "FAIL", "PASS", "PASS", "FAIL"};
  for (std::size_t p = 0; p < 6; ++p) {
    EXPECT_EQ(f.parts[p].serial, serials[p]) << p;
    EXPECT_EQ(f.parts[p].status, statuses[p]) << p;
    EXPECT_EQ(f.parts[p].features.size(), 21u) << p;
    EXPECT_EQ(f.parts[p].characteristics.size(), 38u) << p;
  }
  EXPECT_EQ(f.parts[1].resultsId, 260);
  EXPECT_EQ(f.parts[2].resultsId, 321);

  // Fact 1: hole W1RXXMRA19 (item 165), parts 1 and 6; circles measured without a diameter.
  const auto hole = f.feature("W1RXXMRA19");
  ASSERT_TRUE(hole);
  EXPECT_EQ(f.features[*hole].itemId, 165);
  EXPECT_EQ(*f.features[*hole].diameter, 10.0);
  expectVector(*f.features[*hole].location, 2433.974609375, 800.617431640625, 890.049621582031);
  expectVector(*f.measurement(0, *hole)->location, 2434.01, 801.525055991931, 889.88);
  expectVector(*f.measurement(5, *hole)->location, 2433.88, 801.525055991931, 889.57);
  EXPECT_FALSE(f.measurement(0, *hole)->diameter);
  EXPECT_NEAR(diametralPosition(*f.features[*hole].location, *f.measurement(0, *hole)->location,
                                *f.features[*hole].direction),
              1.076016018900693, 1e-12);
  EXPECT_NEAR(diametralPosition(*f.features[*hole].location, *f.measurement(5, *hole)->location,
                                *f.features[*hole].direction),
              1.632768254314692, 1e-12);
  EXPECT_EQ(measurementOf(f, 0, "W1RXXMRA19P")->status, "PASS");
  EXPECT_EQ(measurementOf(f, 5, "W1RXXMRA19P")->status, "FAIL");

  // Facts 2 and 5: the series over the parts (the README gives 6 decimals).
  const std::vector<double> position{1.076016, 0.846893, 0.870595, 0.897298, 0.927406, 1.632768};
  const std::vector<double> profile{0.224164, 0.148093, 0.201837, 0.228307, 0.228307, 0.183654};
  EXPECT_EQ(f.characteristics[*f.characteristic("W1RISMRA09V")].itemId, 43);
  for (std::size_t p = 0; p < 6; ++p) {
    EXPECT_NEAR(*measurementOf(f, p, "W1RXXMRA19P")->value, position[p], 5e-7) << p;
    EXPECT_NEAR(*measurementOf(f, p, "W1RISMRA09V")->value, profile[p], 5e-7) << p;
  }
  EXPECT_EQ(*measurementOf(f, 0, "W1RXXMRA19P")->value, 1.076016018900693);
  EXPECT_EQ(*measurementOf(f, 5, "W1RXXMRA19P")->value, 1.632768254314692);

  // Facts 3 and 4: what fails in parts 3 and 2.
  auto failing = [&](std::size_t p) {
    std::vector<std::string> names;
    for (const QifCharacteristicMeasurement& m : f.parts[p].characteristics)
      if (m.status == "FAIL") names.push_back(f.characteristics[m.characteristic].name);
    names.erase(std::unique(names.begin(), names.end()), names.end());
    std::sort(names.begin(), names.end());
    return names;
  };
  EXPECT_EQ(failing(2), (std::vector<std::string>{"W1RXXMRA20P", "W1RXXMRA21P"}));
  EXPECT_EQ(*measurementOf(f, 2, "W1RXXMRA20P")->value, 1.25362822729891);
  EXPECT_EQ(*measurementOf(f, 2, "W1RXXMRA21P")->value, 1.355625761986218);
  EXPECT_EQ(failing(1), (std::vector<std::string>{"W1RISMRA07V"}));
  EXPECT_EQ(*measurementOf(f, 1, "W1RISMRA07V")->value, 0.264537055091804);
  const QifCharacteristic& c07 = f.characteristics[*f.characteristic("W1RISMRA07V")];
  EXPECT_EQ(*c07.zone, 0.5);
  EXPECT_EQ(*c07.lowerLimit(f.features), -0.25);
  EXPECT_EQ(*c07.upperLimit(f.features), 0.25);
}

TEST(Qif, WidgetCylindersAndPatternJoin) {
  const std::string path = sample("WIDGET_QIF_RESULTS.QIF");
  METROFIT_REQUIRE_PATH(path);
  const QifFile f = readQifFile(path);
  EXPECT_EQ(f.features.size(), 19u);
  EXPECT_EQ(f.characteristics.size(), 26u);
  ASSERT_EQ(f.parts.size(), 1u);
  EXPECT_EQ(f.parts[0].resultsId, 217);
  EXPECT_EQ(f.parts[0].status, "FAIL");
  EXPECT_EQ(f.parts[0].characteristics.size(), 42u);
  EXPECT_EQ(std::count_if(f.features.begin(), f.features.end(),
                          [](const QifFeature& x) { return x.type == "Cylinder"; }),
            6);
  EXPECT_EQ(std::count_if(f.features.begin(), f.features.end(),
                          [](const QifFeature& x) { return x.type == "Plane"; }),
            5);

  // Fact 1: DATUM_J, an Axis/AxisPoint + Direction cylinder.
  const auto j = f.feature("DATUM_J");
  ASSERT_TRUE(j);
  EXPECT_EQ(f.features[*j].type, "Cylinder");
  expectVector(*f.features[*j].location, -5, 31.1, -71.45);
  expectVector(*f.features[*j].direction, -1, 0, 0);
  EXPECT_EQ(*f.features[*j].diameter, 19.0);
  expectVector(*f.measurement(0, *j)->location, -5, 31.051, -71.282);
  EXPECT_NEAR(*f.measurement(0, *j)->diameter, 19.007, 1e-12);
  const QifCharacteristicMeasurement* d10 = measurementOf(f, 0, "10");
  ASSERT_NE(d10, nullptr);
  EXPECT_NEAR(*d10->value, 19.007, 1e-12);
  EXPECT_EQ(d10->status, "PASS");
  EXPECT_NEAR(*f.characteristics[d10->characteristic].lowerLimit(f.features), -0.13, 1e-12);
  EXPECT_NEAR(*f.characteristics[d10->characteristic].upperLimit(f.features), 0.13, 1e-12);
  const QifCharacteristicMeasurement* p11 = measurementOf(f, 0, "11");
  ASSERT_NE(p11, nullptr);
  EXPECT_EQ(*p11->value, 0.350000000000014);
  EXPECT_NEAR(
      diametralPosition(*f.features[*j].location, *f.measurement(0, *j)->location, *f.features[*j].direction),
      2.0 * std::sqrt(0.049 * 0.049 + 0.168 * 0.168), 1e-12);

  // Fact 2: CYLINDER6.
  EXPECT_EQ(*measurementOf(f, 0, "6", "CYLINDER6")->value, 4.878);
  EXPECT_EQ(measurementOf(f, 0, "6", "CYLINDER6")->status, "FAIL");
  EXPECT_EQ(*measurementOf(f, 0, "7", "CYLINDER6")->value, 0.256257682811652);
  EXPECT_EQ(measurementOf(f, 0, "7", "CYLINDER6")->status, "FAIL");

  // Fact 3: items 82 and 86 list only CYLINDER6 (feature item 78), yet measurements 92 / 93 point to
  // feature measurement 91, CYLINDER7.
  const QifCharacteristic& c82 = f.characteristics[*f.characteristic("6")];
  EXPECT_EQ(c82.itemId, 82);
  ASSERT_EQ(c82.features.size(), 1u);
  EXPECT_EQ(f.features[c82.features[0]].name, "CYLINDER6");
  EXPECT_EQ(f.features[c82.features[0]].itemId, 78);
  const QifCharacteristicMeasurement* m92 = measurementOf(f, 0, "6", "CYLINDER7");
  const QifCharacteristicMeasurement* m93 = measurementOf(f, 0, "7", "CYLINDER7");
  ASSERT_NE(m92, nullptr);
  ASSERT_NE(m93, nullptr);
  EXPECT_EQ(m92->id, 92);
  EXPECT_EQ(m93->id, 93);
  EXPECT_EQ(f.parts[0].features[m92->measured.at(0)].id, 91);
  EXPECT_EQ(*m92->value, 4.89);
  EXPECT_EQ(m92->status, "FAIL");
  EXPECT_EQ(*m93->value, 0.300006666592606);
  EXPECT_EQ(m93->status, "FAIL");
  EXPECT_NEAR(*measurementOf(f, 0, "10", "DATUM_J")->value, 19.007, 1e-12);

  // Facts 4 and 5.
  const QifCharacteristicMeasurement* d19 = measurementOf(f, 0, "19");
  ASSERT_NE(d19, nullptr);
  EXPECT_EQ(*d19->value, 104.63);
  EXPECT_EQ(d19->status, "FAIL");
  EXPECT_EQ(*f.characteristics[d19->characteristic].nominalValue(f.features), 105.0);
  const QifCharacteristicMeasurement* w15 = measurementOf(f, 0, "15");
  ASSERT_NE(w15, nullptr);
  EXPECT_EQ(*w15->value, 9.975014245417);
  EXPECT_EQ(w15->status, "PASS");
  EXPECT_EQ(*f.characteristics[w15->characteristic].nominalValue(f.features), 10.0);
}

TEST(Qif, CmmReportOneRunPerPart) {
  METROFIT_REQUIRE_PATH(sample("SheetMetal_QIF_Results_6_samples.QIF"));
  {
    const CmmTextReport r = qifCmmReport(readQifFile(sample("QIF_Results_Sample.QIF")));
    EXPECT_EQ(r.format, CmmReportFormat::Qif);
    EXPECT_STREQ(toString(r.format), "QIF results file");
    ASSERT_EQ(r.runs.size(), 1u);
    // 13 measurements, the two repeated profile measurements (then 0) left out.
    ASSERT_EQ(r.runs[0].features.size(), 11u);
    const CmmFeature* dia = nullptr;
    const CmmFeature* prof = nullptr;
    for (const CmmFeature& x : r.runs[0].features) {
      if (x.featureName == "6") dia = &x;
      if (x.featureName == "4") prof = &x;
    }
    ASSERT_NE(dia, nullptr);
    EXPECT_EQ(dia->type, "Diameter");
    EXPECT_EQ(dia->featureType, "Circle");
    const CmmValue* v = dia->value("actual");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(*v->nominal, 10.0);
    EXPECT_EQ(v->actual, 9.499476);
    EXPECT_EQ(*v->lower, -0.4);
    EXPECT_EQ(*v->upper, 0.4);
    ASSERT_NE(prof, nullptr);
    EXPECT_EQ(prof->values[0].actual, -0.886195693015347);
    EXPECT_EQ(*prof->values[0].nominal, 0.0);
    EXPECT_EQ(*prof->values[0].lower, -0.5);
    EXPECT_EQ(*prof->values[0].upper, 1.0);
  }
  {
    const CmmTextReport r = qifCmmReport(readQifFile(sample("SheetMetal_QIF_Results_6_samples.QIF")));
    ASSERT_EQ(r.runs.size(), 6u);
    EXPECT_EQ(r.runs[0].serial, "SN5802801");
    EXPECT_EQ(r.runs[5].serial, "SN5802806");
    for (const CmmRun& run : r.runs) EXPECT_EQ(run.features.size(), 21u);
    const CsvTable t = cmmReportFeatureTable(r);
    ASSERT_EQ(t.rowCount(), 6u);
    const std::size_t col = t.requireColumn("W1RXXMRA19P.actual");
    EXPECT_EQ(t.cell(0, col), "1.076016018900693");
    EXPECT_EQ(t.cell(5, col), "1.632768254314692");
  }
  {
    const CmmTextReport r = qifCmmReport(readQifFile(sample("WIDGET_QIF_RESULTS.QIF")));
    ASSERT_EQ(r.runs.size(), 1u);
    std::vector<std::string> keys;
    for (const CmmFeature& x : r.runs[0].features) keys.push_back(x.featureName);
    for (const char* k : {"6@CYLINDER6", "6@CYLINDER7", "7@CYLINDER6", "7@CYLINDER7", "10", "11", "19"})
      EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
    const CsvTable t = cmmReportFeatureTable(r);  // no key twice in a run
    EXPECT_EQ(t.rowCount(), 1u);
    EXPECT_EQ(t.cell(0, t.requireColumn("6@CYLINDER7.actual")), "4.89");
  }
}

TEST(Qif, ProbePoints) {
  const std::string path = sample("QIF_Results_Sample.QIF");
  METROFIT_REQUIRE_PATH(path);
  const QifFile f = readQifFile(path);
  const ProbePointSet all = qifProbePoints(f, 0);
  EXPECT_FALSE(all.hasNormals);  // holes among them: position-only
  // Five measured features; REFCIRC1 (DeterminationMode Set, "a non-measureable reference circle") is
  // given, not measured, and is no probe point.
  ASSERT_EQ(all.points.size(), 5u);
  EXPECT_TRUE(std::none_of(all.points.begin(), all.points.end(),
                           [](const ProbePoint& p) { return p.id == "REFCIRC1"; }));
  const ProbePointSet surface = qifProbePoints(f, 0, QifPoints::Surface);
  ASSERT_TRUE(surface.hasNormals);
  ASSERT_EQ(surface.points.size(), 3u);
  EXPECT_EQ(surface.points[2].id, "SURF2");
  EXPECT_NEAR(surface.points[2].normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(surface.deviations()[2], -0.886195693015347, 1e-9);
  const ProbePointSet holes = qifProbePoints(f, 0, QifPoints::Holes);
  EXPECT_FALSE(holes.hasNormals);
  ASSERT_EQ(holes.points.size(), 2u);
  EXPECT_EQ(holes.points[0].id, "HOLE1");
  expectVector(holes.points[0].nominal, 2433.974609375, 800.617431640625, 890.049621582031);
  expectVector(holes.points[0].measured, 2434.01, 801.52505599193, 889.98);
  EXPECT_THROW(qifProbePoints(f, 1), ValidationError);

  const std::string widget = sample("WIDGET_QIF_RESULTS.QIF");
  METROFIT_REQUIRE_PATH(widget);
  const ProbePointSet w = qifProbePoints(readQifFile(widget), 0, QifPoints::Holes);
  const auto j =
      std::find_if(w.points.begin(), w.points.end(), [](const ProbePoint& p) { return p.id == "DATUM_J"; });
  ASSERT_NE(j, w.points.end());
  // The axis offset: 2 |.| is the position 0.350000000000014 of README fact 1.
  EXPECT_NEAR(2.0 * (j->measured - j->nominal).norm(), 0.350000000000014, 1e-12);
}

// ---- Units and malformed documents, written here --------------------------------------------------------

std::string document(const std::string& units, const std::string& measuredFeatureRef = "3",
                     const std::string& root = "QIFDocument") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<" +
         root + " xmlns=\"http://qifstandards.org/xsd/qif3\" versionQIF=\"3.0.0\">\n" + units +
         "  <Features>\n"
         "    <FeatureDefinitions n=\"1\"><CircleFeatureDefinition id=\"1\"><Diameter>0.5</Diameter>"
         "</CircleFeatureDefinition></FeatureDefinitions>\n"
         "    <FeatureNominals n=\"1\"><CircleFeatureNominal "
         "id=\"2\"><FeatureDefinitionId>1</FeatureDefinitionId>"
         "<Location>1 2 3</Location><Normal>0 0 1</Normal></CircleFeatureNominal></FeatureNominals>\n"
         "    <FeatureItems n=\"1\"><CircleFeatureItem id=\"3\"><FeatureNominalId>2</FeatureNominalId>"
         "<FeatureName>H1</FeatureName></CircleFeatureItem></FeatureItems>\n"
         "  </Features>\n"
         "  <Characteristics>\n"
         "    <CharacteristicDefinitions n=\"1\"><DiameterCharacteristicDefinition id=\"4\"><Tolerance>"
         "<MaxValue>0.01</MaxValue><MinValue>-0.01</MinValue><DefinedAsLimit>false</DefinedAsLimit></"
         "Tolerance>"
         "</DiameterCharacteristicDefinition></CharacteristicDefinitions>\n"
         "    <CharacteristicNominals n=\"1\"><DiameterCharacteristicNominal id=\"5\">"
         "<CharacteristicDefinitionId>4</CharacteristicDefinitionId><TargetValue>0.5</TargetValue>"
         "</DiameterCharacteristicNominal></CharacteristicNominals>\n"
         "    <CharacteristicItems n=\"1\"><DiameterCharacteristicItem id=\"6\"><Name>D1</Name>"
         "<FeatureItemIds "
         "n=\"1\"><Id>3</Id></FeatureItemIds><CharacteristicNominalId>5</CharacteristicNominalId>"
         "</DiameterCharacteristicItem></CharacteristicItems>\n"
         "  </Characteristics>\n"
         "  <Results>\n"
         "    <MeasurementResultsSet n=\"1\">\n"
         "      <MeasurementResults id=\"7\">\n"
         "        <MeasuredFeatures n=\"1\">\n"
         "          <CircleFeatureMeasurement id=\"8\">\n"
         "            <FeatureItemId>" +
         measuredFeatureRef +
         "</FeatureItemId>\n"
         "            <Location>1.001 2 3</Location><Diameter>0.502</Diameter>\n"
         "          </CircleFeatureMeasurement>\n"
         "        </MeasuredFeatures>\n"
         "        <MeasuredCharacteristics><CharacteristicMeasurements n=\"1\">\n"
         "          <DiameterCharacteristicMeasurement id=\"9\"><Status><CharacteristicStatusEnum>PASS"
         "</CharacteristicStatusEnum></Status><CharacteristicItemId>6</CharacteristicItemId>"
         "<FeatureMeasurementIds n=\"1\"><Id>8</Id></FeatureMeasurementIds><Value>0.502</Value>"
         "</DiameterCharacteristicMeasurement>\n"
         "        </CharacteristicMeasurements></MeasuredCharacteristics>\n"
         "      </MeasurementResults>\n"
         "    </MeasurementResultsSet>\n"
         "  </Results>\n"
         "</" +
         root + ">\n";
}

const std::string kInch =
    "  <FileUnits><PrimaryUnits><LinearUnit><SIUnitName>meter</SIUnitName><UnitName>inch</UnitName>"
    "<UnitConversion><Factor>0.0254</Factor></UnitConversion></LinearUnit></PrimaryUnits></FileUnits>\n";

/// The error `text` gives, as what() (one line), and its type.
template <class E>
std::string errorOf(const std::string& text) {
  try {
    qifFromText(text, "bad.qif");
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong type: ") + e.what();
  }
  return "no error";
}

TEST(Qif, InchConvertedToMm) {
  ASSERT_TRUE(looksLikeQif(document(kInch)));
  const QifFile f = qifFromText(document(kInch), "in.qif");
  EXPECT_EQ(f.linearUnit, "inch");
  ASSERT_EQ(f.features.size(), 1u);
  EXPECT_NEAR(f.features[0].location->x(), 25.4, 1e-12);
  EXPECT_NEAR(f.features[0].location->z(), 76.2, 1e-12);
  EXPECT_NEAR(*f.features[0].diameter, 12.7, 1e-12);
  EXPECT_NEAR(f.parts[0].features[0].location->x(), 25.4254, 1e-12);
  EXPECT_NEAR(*f.parts[0].characteristics[0].value, 12.7508, 1e-12);
  EXPECT_NEAR(*f.characteristics[0].target, 12.7, 1e-12);
  EXPECT_NEAR(*f.characteristics[0].lowerLimit(f.features), -0.254, 1e-12);
  EXPECT_NEAR(*f.characteristics[0].upperLimit(f.features), 0.254, 1e-12);
}

TEST(Qif, PrefixedNamespaceAndByteOrderMark) {
  // The same document with every element in a "q:" prefix bound to the QIF 3 namespace, after a BOM.
  std::string text = document(kInch);
  std::string prefixed = "\xEF\xBB\xBF";
  for (std::size_t i = 0; i < text.size(); ++i) {
    prefixed += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      prefixed += '/';
      ++i;
      prefixed += "q:";
    } else if (text[i] == '<' && i + 1 < text.size() &&
               std::isalpha(static_cast<unsigned char>(text[i + 1]))) {
      prefixed += "q:";
    }
  }
  const auto ns = prefixed.find("xmlns=");
  ASSERT_NE(ns, std::string::npos);
  prefixed.replace(ns, 6, "xmlns:q=");
  ASSERT_TRUE(looksLikeQif(prefixed));
  const QifFile f = qifFromText(prefixed, "q.qif");
  ASSERT_EQ(f.parts.size(), 1u);
  EXPECT_EQ(f.features[0].name, "H1");
  EXPECT_NEAR(*f.parts[0].characteristics[0].value, 12.7508, 1e-12);
}

TEST(Qif, MalformedDocumentsGiveOneLineErrors) {
  const std::string good = document(kInch);
  // A truncated file: not well-formed XML, at its last line.
  const std::string truncated = good.substr(0, good.find("</MeasuredFeatures>"));
  const long lastLine = static_cast<long>(std::count(truncated.begin(), truncated.end(), '\n')) + 1;
  const std::string t = errorOf<ParseError>(truncated);
  EXPECT_EQ(t.rfind("bad.qif:" + std::to_string(lastLine) + ":", 0), 0u) << t;
  EXPECT_NE(t.find("not well-formed XML: the text ends before its elements are closed"), std::string::npos)
      << t;
  // A wrong root.
  const std::string root = errorOf<ValidationError>(document(kInch, "3", "QIFPlan"));
  EXPECT_EQ(root, "bad.qif:2: root element <QIFPlan> is not a QIF QIFDocument") << root;
  // Another namespace.
  std::string qif2 = good;
  qif2.replace(qif2.find("xsd/qif3"), 8, "xsd/qif2");
  EXPECT_NE(errorOf<ValidationError>(qif2).find("not in the QIF 3 namespace"), std::string::npos);
  // No FileUnits.
  EXPECT_EQ(errorOf<ValidationError>(document("")), "bad.qif:2: QIFDocument has no FileUnits");
  // An id referenced but absent: the measurement (line 18) names feature item 33.
  EXPECT_EQ(errorOf<ValidationError>(document(kInch, "33")),
            "bad.qif:18: CircleFeatureMeasurement 8: FeatureItemId 33 names no FeatureItem");
  // A number that is not one, at its element's line.
  EXPECT_EQ(errorOf<ParseError>(document(kInch, "x")),
            "bad.qif:19: CircleFeatureMeasurement 8 FeatureItemId: 'x' is not an integer id");
  for (const std::string& bad : {truncated, document(kInch, "33"), document("")}) {
    const std::string e = errorOf<InputError>(bad);
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_FALSE(looksLikeQif("<?xml version=\"1.0\"?>\n<DMIS/>"));
}

TEST(Qif, RealSampleWithAMissingReferenceNamesItsLine) {
  const std::string path = sample("QIF_Results_Sample.QIF");
  METROFIT_REQUIRE_PATH(path);
  std::string text = readFile(path);
  const std::string ref =
      "<Id>47</Id>\n              </FeatureMeasurementIds>\n              <NonConformanceDesignator>1234";
  const auto at = text.find(ref);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 11, "<Id>4700</Id>");
  EXPECT_EQ(errorOf<ValidationError>(text),
            "bad.qif:880: DiameterCharacteristicMeasurement 51: FeatureMeasurementIds 4700 names no "
            "FeatureMeasurement of MeasurementResults 89");
  // Truncated in the middle of the results.
  const std::string cut = readFile(path).substr(0, 30000);
  const long lastLine = static_cast<long>(std::count(cut.begin(), cut.end(), '\n')) + 1;
  const std::string e = errorOf<ParseError>(cut);
  EXPECT_EQ(e.rfind("bad.qif:" + std::to_string(lastLine) + ": not well-formed XML: the text ends", 0), 0u)
      << e;
  // Not XML at all.
  EXPECT_EQ(errorOf<ParseError>("hello"), "bad.qif:1: not well-formed XML: No document element found");
}

}  // namespace
}  // namespace metrofit
