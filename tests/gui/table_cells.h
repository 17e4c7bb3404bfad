#pragma once
// A table cell read as a number, checked: a cell that is missing or does not parse (as QString::toDouble
// reads it, '.' decimals: what the import preview writes) fails the test instead of reading as 0.
#include <gtest/gtest.h>

#include <QTableWidget>
#include <limits>

namespace metrofit::test {

inline double cellNumber(const QTableWidget* table, int row, int column) {
  const QTableWidgetItem* item = table ? table->item(row, column) : nullptr;
  if (!item) {
    ADD_FAILURE() << "no cell (" << row << ", " << column << ")";
    return std::numeric_limits<double>::quiet_NaN();
  }
  bool ok = false;
  const double v = item->text().toDouble(&ok);
  if (!ok) {
    ADD_FAILURE() << "cell (" << row << ", " << column << ") '" << item->text().toStdString()
                  << "' is not a number";
    return std::numeric_limits<double>::quiet_NaN();
  }
  return v;
}

}  // namespace metrofit::test
