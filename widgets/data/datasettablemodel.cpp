#include "widgets/data/datasettablemodel.h"

#include <QApplication>
#include <QColor>
#include <QLocale>
#include <QStyle>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "core/project/dataset_content.h"
#include "widgets/common/palette.h"

namespace metrofit {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A cell as a number in the table's decimal form ("20,5" in a decimal-comma file), else NaN.
double cellNumber(const std::string& cell, char decimal) {
  if (cell.empty()) return kNaN;
  double v = 0.0;
  if (decimal == ',') {
    if (cell.find('.') != std::string::npos) return kNaN;
    std::string t = cell;
    for (char& c : t)
      if (c == ',') c = '.';
    return parseNumber(t, &v) ? v : kNaN;
  }
  return parseNumber(cell, &v) ? v : kNaN;
}

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

QColor outOfToleranceBackground() {
  return QColor(0xfb, 0xdc, 0xdc);
}

}  // namespace

DatasetTableModel::DatasetTableModel(QObject* parent) : QAbstractTableModel(parent) {}
DatasetTableModel::~DatasetTableModel() = default;

bool DatasetTableModel::isFeatureTable() const {
  return content_ && content_->shape == DatasetContent::Shape::Features;
}

void DatasetTableModel::setContent(std::shared_ptr<const DatasetContent> content) {
  beginResetModel();
  content_ = std::move(content);
  fields_.clear();
  commonUnit_.clear();
  numbers_.clear();
  numeric_.clear();
  if (isFeatureTable()) {
    const auto& rows = content_->features;
    bool parts = false;
    bool oneUnit = !rows.empty();
    for (const FeatureTableRow& r : rows) {
      parts = parts || !r.part.empty();
      oneUnit = oneUnit && r.unit == rows.front().unit;
    }
    if (oneUnit) commonUnit_ = q(rows.front().unit);
    if (parts) fields_.push_back(Field::Part);
    fields_.insert(fields_.end(), {Field::Feature, Field::Characteristic});
    if (!oneUnit) fields_.push_back(Field::Unit);
    fields_.insert(fields_.end(), {Field::Nominal, Field::Actual, Field::Deviation, Field::Lower,
                                   Field::Upper, Field::Status});
    for (Field f : fields_) {
      std::vector<double> column(rows.size(), kNaN);
      const bool isNumber = f == Field::Nominal || f == Field::Actual || f == Field::Deviation ||
                            f == Field::Lower || f == Field::Upper;
      if (isNumber) {
        for (std::size_t r = 0; r < rows.size(); ++r) {
          const FeatureTableRow& row = rows[r];
          const std::optional<double> v = f == Field::Nominal     ? row.nominal
                                          : f == Field::Actual    ? row.actual
                                          : f == Field::Deviation ? row.deviation
                                          : f == Field::Lower     ? row.lower
                                                                  : row.upper;
          if (v) column[r] = *v;
        }
      }
      numbers_.push_back(std::move(column));
      numeric_.push_back(isNumber);
    }
  } else if (content_) {
    const CsvTable& t = content_->table;
    for (std::size_t c = 0; c < t.columnCount(); ++c) {
      std::vector<double> column(t.rowCount(), kNaN);
      std::size_t filled = 0, numbers = 0;
      for (std::size_t r = 0; r < t.rowCount(); ++r) {
        const std::string& cell = t.cell(r, c);
        if (cell.empty()) continue;
        ++filled;
        column[r] = cellNumber(cell, t.dialect().decimal);
        numbers += std::isnan(column[r]) ? 0 : 1;
      }
      numbers_.push_back(std::move(column));
      numeric_.push_back(numbers > 0 && 2 * numbers >= filled);
    }
  }
  endResetModel();
}

int DatasetTableModel::rowCount(const QModelIndex& parent) const {
  if (parent.isValid() || !content_) return 0;
  return static_cast<int>(isFeatureTable() ? content_->features.size() : content_->table.rowCount());
}

int DatasetTableModel::columnCount(const QModelIndex& parent) const {
  if (parent.isValid() || !content_) return 0;
  return static_cast<int>(isFeatureTable() ? fields_.size() : content_->table.columnCount());
}

QString DatasetTableModel::numberText(double value) const {
  QLocale locale;
  locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
  return locale.toString(value, 'g', QLocale::FloatingPointShortest);
}

QString DatasetTableModel::featureText(int row, Field field) const {
  const FeatureTableRow& r = content_->features[static_cast<std::size_t>(row)];
  switch (field) {
    case Field::Part:
      return q(r.part);
    case Field::Feature:
      return q(r.feature);
    case Field::Characteristic:
      return q(r.characteristic);
    case Field::Unit:
      return q(r.unit);
    case Field::Status:
      if (r.outOfTolerance) return tr("out of tolerance");
      if (!r.lower && !r.upper) return tr("no tolerance");
      return r.deviation ? tr("in tolerance") : QString();
    default:
      break;
  }
  return {};
}

QVariant DatasetTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || !content_ || index.row() >= rowCount() || index.column() >= columnCount())
    return {};
  const int row = index.row(), col = index.column();
  const double value = numbers_[static_cast<std::size_t>(col)][static_cast<std::size_t>(row)];
  if (isFeatureTable()) {
    const Field field = fields_[static_cast<std::size_t>(col)];
    const bool oot = outOfTolerance(row);
    switch (role) {
      case Qt::DisplayRole:
        if (numeric_[static_cast<std::size_t>(col)]) return std::isnan(value) ? QString() : numberText(value);
        return featureText(row, field);
      case SortRole:
        if (numeric_[static_cast<std::size_t>(col)])
          return std::isnan(value) ? std::numeric_limits<double>::max() : value;
        return featureText(row, field);
      case OutOfToleranceRole:
        return oot;
      case Qt::BackgroundRole:
        if (oot) return outOfToleranceBackground();
        return {};
      case Qt::ForegroundRole:
        if (oot && (field == Field::Status || field == Field::Deviation)) return palette::badText();
        return {};
      case Qt::DecorationRole:
        if (oot && field == Field::Status)
          return QApplication::style()->standardIcon(QStyle::SP_MessageBoxWarning);
        return {};
      case Qt::TextAlignmentRole:
        if (numeric_[static_cast<std::size_t>(col)])
          return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
        return {};
      case Qt::ToolTipRole: {
        const FeatureTableRow& r = content_->features[static_cast<std::size_t>(row)];
        QString tip = tr("Line %1 of the file").arg(r.line);
        if (oot && r.deviation)
          tip += QLatin1Char('\n') + tr("Deviation %1 %2 is outside the tolerance %3 … %4")
                                         .arg(numberText(*r.deviation), q(r.unit),
                                              r.lower ? numberText(*r.lower) : QStringLiteral("−∞"),
                                              r.upper ? numberText(*r.upper) : QStringLiteral("+∞"));
        else if (oot)
          tip += QLatin1Char('\n') + tr("The report marks this value out of tolerance");
        return tip;
      }
      default:
        return {};
    }
  }
  const CsvTable& t = content_->table;
  const bool isNumber = !std::isnan(value);
  switch (role) {
    case Qt::DisplayRole:
      return isNumber ? numberText(value)
                      : q(t.cell(static_cast<std::size_t>(row), static_cast<std::size_t>(col)));
    case SortRole:
      if (numeric_[static_cast<std::size_t>(col)])
        return isNumber ? value : std::numeric_limits<double>::max();
      return q(t.cell(static_cast<std::size_t>(row), static_cast<std::size_t>(col)));
    case Qt::TextAlignmentRole:
      if (isNumber) return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
      return {};
    default:
      return {};
  }
}

QString DatasetTableModel::columnName(int column) const {
  if (!content_ || column < 0 || column >= columnCount()) return {};
  if (!isFeatureTable()) return q(content_->table.header()[static_cast<std::size_t>(column)]);
  switch (fields_[static_cast<std::size_t>(column)]) {
    case Field::Part:
      return tr("Part");
    case Field::Feature:
      return tr("Feature");
    case Field::Characteristic:
      return tr("Characteristic");
    case Field::Unit:
      return tr("Unit");
    case Field::Nominal:
      return tr("Nominal");
    case Field::Actual:
      return tr("Actual");
    case Field::Deviation:
      return tr("Deviation");
    case Field::Lower:
      return tr("Lower tol.");
    case Field::Upper:
      return tr("Upper tol.");
    case Field::Status:
      return tr("Status");
  }
  return {};
}

QString DatasetTableModel::columnUnit(int column) const {
  if (!content_ || column < 0 || column >= columnCount()) return {};
  if (!isFeatureTable()) return q(content_->units[static_cast<std::size_t>(column)]);
  return numeric_[static_cast<std::size_t>(column)] ? commonUnit_ : QString();
}

QVariant DatasetTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation == Qt::Vertical) {
    if (role == Qt::DisplayRole) return section + 1;
    return {};
  }
  if (section < 0 || section >= columnCount()) return {};
  if (role == Qt::DisplayRole) {
    const QString unit = columnUnit(section);
    const QString name = columnName(section);
    // A file's own name that states its unit already ("Zeit [min]") is not given it twice.
    if (unit.isEmpty() || name.endsWith(QLatin1Char(']')) || name.endsWith(QLatin1Char(')'))) return name;
    return QStringLiteral("%1 [%2]").arg(name, unit);
  }
  if (role == Qt::ToolTipRole && !isFeatureTable()) {
    const QString file = q(content_->fileColumns[static_cast<std::size_t>(section)]);
    const QString name = columnName(section);
    if (file != name) return tr("The file's column “%1”, read as %2").arg(file, name);
    return tr("The file's column “%1”").arg(file);
  }
  if (role == Qt::ToolTipRole && fields_[static_cast<std::size_t>(section)] == Field::Deviation)
    return tr("Actual − nominal (plain sign; OGP prints locations with the sign of the nominal)");
  return {};
}

bool DatasetTableModel::isNumeric(int column) const {
  return column >= 0 && static_cast<std::size_t>(column) < numeric_.size() &&
         numeric_[static_cast<std::size_t>(column)];
}

double DatasetTableModel::number(int row, int column) const {
  if (column < 0 || static_cast<std::size_t>(column) >= numbers_.size() || row < 0 ||
      static_cast<std::size_t>(row) >= numbers_[static_cast<std::size_t>(column)].size())
    return kNaN;
  return numbers_[static_cast<std::size_t>(column)][static_cast<std::size_t>(row)];
}

int DatasetTableModel::timeColumn() const {
  if (!content_ || isFeatureTable()) return -1;
  const auto& header = content_->table.header();
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == "time_s" || header[c] == "time_min" || header[c] == "time_h") return static_cast<int>(c);
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string& u = content_->units[c];
    if ((u == "s" || u == "min" || u == "h") && numeric_[c]) return static_cast<int>(c);
  }
  return -1;
}

bool DatasetTableModel::rowContains(int row, const QString& text) const {
  if (text.isEmpty()) return true;
  if (!content_ || row < 0 || row >= rowCount()) return false;
  if (isFeatureTable()) {
    for (int c = 0; c < columnCount(); ++c)
      if (data(index(row, c)).toString().contains(text, Qt::CaseInsensitive)) return true;
    return false;
  }
  const auto lower = [](std::string s) {
    for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return s;
  };
  const std::string needle = lower(text.toStdString());
  std::string other = needle;
  for (char& ch : other) ch = ch == ',' ? '.' : ch == '.' ? ',' : ch;
  const auto contains = [](const std::string& hay, const std::string& n) {
    return std::search(hay.begin(), hay.end(), n.begin(), n.end(), [](char a, char b) {
             return std::tolower(static_cast<unsigned char>(a)) == b;
           }) != hay.end();
  };
  const CsvTable& t = content_->table;
  for (std::size_t c = 0; c < t.columnCount(); ++c) {
    const std::string& cell = t.cell(static_cast<std::size_t>(row), c);
    if (contains(cell, needle) || (other != needle && contains(cell, other))) return true;
  }
  return false;
}

bool DatasetTableModel::outOfTolerance(int row) const {
  return isFeatureTable() && row >= 0 && static_cast<std::size_t>(row) < content_->features.size() &&
         content_->features[static_cast<std::size_t>(row)].outOfTolerance;
}

}  // namespace metrofit
