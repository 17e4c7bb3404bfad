#pragma once
// Copying from result tables: enableTableCopy() gives a QTableView / QTableWidget Ctrl+C and a
// context menu with "Copy" and "Select all". The copied text is tab-separated with the column
// headers as its first line (what a spreadsheet expects): the rows that have a selected cell and the
// columns that have one, a cell not selected left empty; with nothing selected, the whole table.
// Hidden rows and columns are left out, columns come in the order shown.
#include <QString>

class QTableView;

namespace metrofit {

/// Adds the "Copy" (Ctrl+C) and "Select all" actions to the table's context menu. Twice changes nothing.
void enableTableCopy(QTableView* table);
/// The text enableTableCopy() puts on the clipboard (lines end with '\n').
QString tableSelectionText(const QTableView* table);
/// Puts tableSelectionText() on the clipboard.
void copyTableSelection(const QTableView* table);

}  // namespace metrofit
