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

std::optional<QString> storedStateText(const StoredResult& stored, const StoredStateTexts& texts) {
  const QString* text = nullptr;
  switch (stored.state) {
    case StoredResultState::None:
      return QString();
    case StoredResultState::Current:
      return std::nullopt;
    case StoredResultState::SettingsChanged:
      text = &texts.settingsChanged;
      break;
    case StoredResultState::DataChanged:
      text = &texts.dataChanged;
      break;
    case StoredResultState::DataMissing:
      text = &texts.dataMissing;
      break;
  }
  if (!text) return QString();
  return text->arg(storedTimeText(stored.computed));
}

double storedFigure(const nlohmann::json& block, const char* key, double missing) {
  if (!block.is_object()) return missing;
  const auto it = block.find(key);
  return it != block.end() && it->is_number() ? it->get<double>() : missing;
}

long long storedCount(const nlohmann::json& block, const char* key) {
  if (!block.is_object()) return 0;
  const auto it = block.find(key);
  return it != block.end() && it->is_number_integer() ? it->get<long long>() : 0;
}

}  // namespace metrofit
