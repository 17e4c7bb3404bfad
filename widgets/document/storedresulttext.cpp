#include "widgets/document/storedresulttext.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>

namespace metrofit {

QString storedTimeText(const std::string& computed) {
  QDateTime t = QDateTime::fromString(QString::fromStdString(computed), Qt::ISODate);
  if (!t.isValid()) return QCoreApplication::translate("metrofit::StoredResult", "at an unknown time");
  t = t.toUTC();
  return QLocale().toString(t, QLocale::ShortFormat) + QStringLiteral(" UTC");
}

}  // namespace metrofit
