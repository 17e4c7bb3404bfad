// Units in column and role names (core/io/units.h) and the conversion of a mapped column
// (CsvTable::mapColumns). The factors are checked against their definitions (SI, and the inch as
// exactly 25.4 mm since the 1959 international yard and pound agreement), written here, not taken
// from the code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/units.h"

namespace metrofit {
namespace {

TEST(Units, ColumnNamesGiveTheirBracketUnitAsCoreSpellsIt) {
  EXPECT_EQ(columnNameUnit("Zeit [min]"), "min");
  EXPECT_EQ(columnNameUnit("Soll X [\xC2\xB5m]"), "um");  // µ (micro sign)
  EXPECT_EQ(columnNameUnit("Soll X [\xCE\xBCm]"), "um");  // μ (Greek mu)
  EXPECT_EQ(columnNameUnit("Ist (inch)"), "inch");
  EXPECT_EQ(columnNameUnit("Ist [Zoll] "), "inch");
  EXPECT_EQ(columnNameUnit("Temperatur T1 [\xC2\xB0"
                           "C]"),
            "degC");
  EXPECT_EQ(columnNameUnit("Drehzahl [1/min]"), "rpm");
  EXPECT_EQ(columnNameUnit("X [m]"), "m");
  EXPECT_EQ(columnNameUnit("Zeit [s]"), "s");
  EXPECT_EQ(columnNameUnit("Winkel [rad]"), "rad");
  EXPECT_EQ(columnNameUnit("Zeit"), "");
  EXPECT_EQ(columnNameUnit("Zeit [furlong]"), "");
}

TEST(Units, RolesHaveTheUnitOfTheirSuffix) {
  EXPECT_EQ(roleUnit("nominal_mm"), "mm");
  EXPECT_EQ(roleUnit("deviation_um"), "um");
  EXPECT_EQ(roleUnit("time_s"), "s");
  EXPECT_EQ(roleUnit("time_min"), "min");
  EXPECT_EQ(roleUnit("time_h"), "h");
  EXPECT_EQ(roleUnit("angle_deg"), "deg");
  EXPECT_EQ(roleUnit("spindle_rpm"), "rpm");
  EXPECT_EQ(roleUnit("qx"), "mm");
  EXPECT_EQ(roleUnit("pz"), "mm");
  EXPECT_EQ(roleUnit("nx"), "");
  EXPECT_EQ(roleUnit("id"), "");
  EXPECT_EQ(roleUnit("part"), "");
}

TEST(Units, FactorsFollowTheirDefinitions) {
  EXPECT_DOUBLE_EQ(*unitFactor("inch", "mm"), 25.4);
  EXPECT_DOUBLE_EQ(*unitFactor("mm", "inch"), 1.0 / 25.4);
  EXPECT_DOUBLE_EQ(*unitFactor("um", "mm"), 1e-3);
  EXPECT_DOUBLE_EQ(*unitFactor("mm", "um"), 1e3);
  EXPECT_DOUBLE_EQ(*unitFactor("nm", "um"), 1e-3);
  EXPECT_DOUBLE_EQ(*unitFactor("m", "mm"), 1e3);
  EXPECT_DOUBLE_EQ(*unitFactor("cm", "mm"), 10.0);
  EXPECT_DOUBLE_EQ(*unitFactor("s", "min"), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(*unitFactor("h", "min"), 60.0);
  EXPECT_DOUBLE_EQ(*unitFactor("h", "s"), 3600.0);
  EXPECT_DOUBLE_EQ(*unitFactor("rad", "deg"), 180.0 / std::numbers::pi);
  EXPECT_DOUBLE_EQ(*unitFactor("mm", "mm"), 1.0);
  EXPECT_FALSE(unitFactor("degC", "mm"));
  EXPECT_FALSE(unitFactor("s", "mm"));
  EXPECT_FALSE(unitFactor("K", "degC")) << "an offset, not a factor";
  EXPECT_FALSE(unitFactor("", "mm"));
}

TEST(Units, AMappedColumnIsReadInTheRolesUnit) {
  CsvReadOptions o;
  o.dialect = {';', ','};
  o.columnMap = {{"nominal_mm", "Soll [\xC2\xB5m]"}, {"measured_mm", "Ist [inch]"}, {"time_min", "Zeit [s]"}};
  const CsvTable t = parseCsv(
      "Zeit [s];Soll [\xC2\xB5m];Ist [inch];Bemerkung [\xC2\xB5m]\n"
      "90;12500;0,5;7\n",
      "shop.csv", o);
  EXPECT_DOUBLE_EQ(t.number(0, static_cast<std::size_t>(t.columnIndex("time_min"))), 1.5);
  EXPECT_DOUBLE_EQ(t.number(0, static_cast<std::size_t>(t.columnIndex("nominal_mm"))), 12.5);
  EXPECT_DOUBLE_EQ(t.number(0, static_cast<std::size_t>(t.columnIndex("measured_mm"))), 12.7);
  // A column that is not mapped keeps the file's unit and values.
  EXPECT_DOUBLE_EQ(t.number(0, static_cast<std::size_t>(t.columnIndex("Bemerkung [\xC2\xB5m]"))), 7.0);
  EXPECT_EQ(t.cell(0, static_cast<std::size_t>(t.columnIndex("nominal_mm"))), "12500")
      << "cells stay as written";
}

TEST(Units, AColumnOfAnotherQuantityIsRefusedNamingBothUnits) {
  CsvReadOptions o;
  o.columnMap = {{"nominal_mm",
                  "T1 [\xC2\xB0"
                  "C]"}};
  try {
    (void)parseCsv(
        "T1 [\xC2\xB0"
        "C],x\n20,1\n",
        "t.csv", o);
    FAIL() << "a temperature read as a length";
  } catch (const ValidationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("t.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("nominal_mm"), std::string::npos) << what;
    EXPECT_NE(what.find("degC"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace metrofit
