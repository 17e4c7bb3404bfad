#include "core/io/mtconnect.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <pugixml.hpp>
#include <set>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/file_io.h"
#include "core/io/xml_text.h"

namespace metrofit {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

using xml::localName;

/// Days from 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

bool isConditionLevel(std::string_view v) {
  const std::string u = upper(trimmed(v));
  return u == "NORMAL" || u == "WARNING" || u == "FAULT";
}

bool unavailable(std::string_view v) {
  const std::string_view t = trimmed(v);
  return t.empty() || upper(t) == "UNAVAILABLE";
}

}  // namespace

const MtcDataItem* MtcDevices::find(std::string_view key) const {
  for (const MtcDataItem& i : items)
    if (i.id == key) return &i;
  for (const MtcDataItem& i : items)
    if (i.name == key) return &i;
  for (const MtcDataItem& i : items)
    if (!i.source.empty() && i.source == key) return &i;
  return nullptr;
}

bool looksLikeMtconnectDevices(std::string_view text) {
  return xml::rootName(text) == "MTConnectDevices";
}

bool looksLikeMtconnectStreams(std::string_view text) {
  return xml::rootName(text) == "MTConnectStreams";
}

bool looksLikeShdr(std::string_view text) {
  std::size_t pos = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
  for (int n = 0; n < 50 && pos < text.size(); ++n) {
    const auto nl = text.find('\n', pos);
    const std::string_view line =
        trimmed(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    if (line.empty() || line.front() == '*') continue;
    const auto bar = line.find('|');
    return bar != std::string_view::npos && parseIsoTimestamp(line.substr(0, bar)).has_value();
  }
  return false;
}

std::optional<double> parseIsoTimestamp(std::string_view t) {
  t = trimmed(t);
  // YYYY-MM-DDThh:mm:ss
  if (t.size() < 19 || t[4] != '-' || t[7] != '-' || (t[10] != 'T' && t[10] != 't' && t[10] != ' ') ||
      t[13] != ':' || t[16] != ':')
    return std::nullopt;
  auto digits = [&](std::size_t at, std::size_t n) -> std::optional<int> {
    int v = 0;
    for (std::size_t k = at; k < at + n; ++k) {
      if (!std::isdigit(static_cast<unsigned char>(t[k]))) return std::nullopt;
      v = v * 10 + (t[k] - '0');
    }
    return v;
  };
  const auto y = digits(0, 4), mo = digits(5, 2), d = digits(8, 2), h = digits(11, 2), mi = digits(14, 2),
             s = digits(17, 2);
  if (!y || !mo || !d || !h || !mi || !s || *mo < 1 || *mo > 12 || *d < 1 || *d > 31 || *h > 24 || *mi > 59 ||
      *s > 60)
    return std::nullopt;
  double seconds =
      static_cast<double>(daysFromCivil(*y, static_cast<unsigned>(*mo), static_cast<unsigned>(*d))) *
          86400.0 +
      *h * 3600.0 + *mi * 60.0 + *s;
  std::size_t k = 19;
  if (k < t.size() && (t[k] == '.' || t[k] == ',')) {
    double scale = 0.1, fraction = 0.0;
    ++k;
    const std::size_t first = k;
    for (; k < t.size() && std::isdigit(static_cast<unsigned char>(t[k])); ++k, scale /= 10.0)
      fraction += (t[k] - '0') * scale;
    if (k == first) return std::nullopt;
    seconds += fraction;
  }
  if (k == t.size()) return seconds;
  if ((t[k] == 'Z' || t[k] == 'z') && k + 1 == t.size()) return seconds;
  if ((t[k] == '+' || t[k] == '-') && t.size() - k == 6 && t[k + 3] == ':') {
    const auto oh = digits(k + 1, 2), om = digits(k + 4, 2);
    if (!oh || !om) return std::nullopt;
    const double offset = *oh * 3600.0 + *om * 60.0;
    return t[k] == '+' ? seconds - offset : seconds + offset;
  }
  return std::nullopt;
}

MtcDevices mtconnectDevicesFromText(std::string_view text, const std::string& source) {
  const xml::LineIndex lines(text);
  pugi::xml_document doc;
  xml::parse(doc, text, source, lines);
  const pugi::xml_node root = doc.document_element();
  if (localName(root) != "MTConnectDevices")
    throw ParseError(
        ErrorContext{source, lines.of(root.offset_debug()), 0, {}},
        "not an MTConnectDevices document (its root element is '" + std::string(root.name()) + "')");
  MtcDevices out;
  out.source = source;
  // Depth-first: the device and the component of each DataItem are its nearest ancestors of those kinds.
  struct Walker : pugi::xml_tree_walker {
    MtcDevices* out;
    bool for_each(pugi::xml_node& n) override {
      if (n.type() != pugi::node_element || localName(n) != "DataItem") return true;
      MtcDataItem item;
      item.id = n.attribute("id").value();
      item.name = n.attribute("name").value();
      item.category = upper(n.attribute("category").value());
      item.type = n.attribute("type").value();
      item.subType = n.attribute("subType").value();
      item.units = n.attribute("units").value();
      item.representation = upper(n.attribute("representation").value());
      for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
        if (c.type() == pugi::node_element && localName(c) == "Source") {
          item.source = std::string(trimmed(c.child_value()));
          if (item.source.empty()) item.source = c.attribute("dataItemId").value();
        }
      // DataItem -> DataItems -> the component.
      const pugi::xml_node component = n.parent().parent();
      if (component) item.component = std::string(localName(component));
      for (pugi::xml_node a = n.parent(); a; a = a.parent())
        if (localName(a) == "Device" || localName(a) == "Agent") {
          item.device = a.attribute("name").value();
          break;
        }
      out->items.push_back(std::move(item));
      return true;
    }
  } walker;
  walker.out = &out;
  pugi::xml_node top = root;
  top.traverse(walker);
  if (out.items.empty())
    throw ValidationError(ErrorContext{source, 0, 0, {}},
                          "the MTConnectDevices document declares no DataItem");
  return out;
}

MtcDevices readMtconnectDevices(const std::string& path) {
  return mtconnectDevicesFromText(readFile(path, 64u << 20), displayPath(path));
}

std::optional<std::string> devicesFileBeside(const std::string& logPath) {
  if (logPath.empty() || logPath == "-") return std::nullopt;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folder = fs::absolute(fs::path(logPath), ec).parent_path();
  if (ec) return std::nullopt;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    std::string name = entry.path().filename().string();
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "devices.xml" && entry.is_regular_file(ec)) return entry.path().string();
  }
  return std::nullopt;
}

namespace {
/// True when fields[from], ..., fields[from + n - 1] are blank: what follows UNAVAILABLE in an unavailable
/// condition (`key|UNAVAILABLE||||`); a sample pair `key|UNAVAILABLE|key2|v2|...` has keys and values there.
bool emptyFields(const std::vector<std::string_view>& fields, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < from + n && i < fields.size(); ++i)
    if (!trimmed(fields[i]).empty()) return false;
  return true;
}
}  // namespace

MtcLog shdrFromText(std::string_view text, const std::string& source, const MtcDevices* devices) {
  MtcLog log;
  log.source = source;
  std::size_t pos = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  long lineNo = 0;
  std::string multiline;  // the marker of an open asset block
  long multilineStart = 0;
  std::vector<std::string_view> fields;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view line =
        text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!multiline.empty()) {
      if (trimmed(line) == multiline) multiline.clear();
      continue;
    }
    const std::string_view t = trimmed(line);
    if (t.empty()) continue;
    if (t.front() == '*') {
      ++log.commands;
      continue;
    }
    fields.clear();
    for (std::size_t start = 0;;) {
      const auto bar = line.find('|', start);
      fields.push_back(
          line.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start));
      if (bar == std::string_view::npos) break;
      start = bar + 1;
    }
    const auto time = parseIsoTimestamp(fields[0]);
    if (!time)
      throw ParseError(ErrorContext{source, lineNo, 1, "timestamp"},
                       "'" + std::string(trimmed(fields[0]).substr(0, 40)) +
                           "' is not an ISO 8601 time (YYYY-MM-DDThh:mm:ss[.fff]Z)");
    if (fields.size() >= 2 && !trimmed(fields[1]).empty() && trimmed(fields[1]).front() == '@') {
      // An asset command; a multiline block follows when its last field opens one.
      ++log.assets;
      const std::string_view last = trimmed(fields.back());
      if (last.substr(0, 13) == "--multiline--") {
        multiline = std::string(last);
        multilineStart = lineNo;
      }
      continue;
    }
    std::size_t k = 1;
    while (k < fields.size()) {
      const std::string key(trimmed(fields[k]));
      if (key.empty()) {
        ++k;
        continue;
      }
      const MtcDataItem* item = devices ? devices->find(key) : nullptr;
      const std::size_t rest = fields.size() - k - 1;  // fields after the key
      MtcObservation o;
      o.timeS = *time;
      o.key = key;
      o.line = lineNo;
      std::size_t take = 1;
      if (item ? (item->category == "CONDITION" || upper(item->type) == "ALARM")
               : (rest >= 5 && isConditionLevel(fields[k + 1])) ||
                     (rest == 5 && upper(trimmed(fields[k + 1])) == "UNAVAILABLE" &&
                      emptyFields(fields, k + 2, 4))) {
        o.condition = true;
        take = std::min<std::size_t>(5, rest);
      } else if (item && upper(item->type) == "MESSAGE") {
        take = std::min<std::size_t>(2, rest);
      } else if (item && item->representation == "TIME_SERIES") {
        take = std::min<std::size_t>(3, rest);
      }
      if (rest == 0) break;  // a key without a value at the end of the line
      o.value = std::string(trimmed(fields[k + 1]));
      if (item && upper(item->type) == "MESSAGE" && take == 2) o.value = std::string(trimmed(fields[k + 2]));
      if (item && item->representation == "TIME_SERIES") o.value = "TIME_SERIES";  // not a scalar
      log.observations.push_back(std::move(o));
      k += 1 + take;
    }
  }
  if (!multiline.empty())
    throw ParseError(
        ErrorContext{source, multilineStart, 0, {}},
        "the asset block opened here is not closed by its " + multiline + " line (a truncated file?)");
  return log;
}

MtcLog mtconnectStreamsFromText(std::string_view text, const std::string& source) {
  const xml::LineIndex lines(text);
  pugi::xml_document doc;
  xml::parse(doc, text, source, lines);
  const pugi::xml_node root = doc.document_element();
  if (localName(root) != "MTConnectStreams")
    throw ParseError(
        ErrorContext{source, lines.of(root.offset_debug()), 0, {}},
        "not an MTConnectStreams document (its root element is '" + std::string(root.name()) + "')");
  MtcLog log;
  log.source = source;
  log.streams = true;
  struct Walker : pugi::xml_tree_walker {
    MtcLog* log;
    const xml::LineIndex* lines;
    const std::string* source;
    bool for_each(pugi::xml_node& n) override {
      if (n.type() != pugi::node_element) return true;
      const std::string_view group = localName(n.parent());
      if (group != "Samples" && group != "Events" && group != "Condition") return true;
      MtcObservation o;
      o.line = lines->of(n.offset_debug());
      o.key = n.attribute("dataItemId").value();
      if (o.key.empty()) o.key = n.attribute("name").value();
      const std::string stamp = n.attribute("timestamp").value();
      const auto time = parseIsoTimestamp(stamp);
      if (!time)
        throw ParseError(ErrorContext{*source, o.line, 0, "timestamp"},
                         "'" + stamp.substr(0, 40) + "' is not an ISO 8601 time");
      o.timeS = *time;
      o.condition = group == "Condition";
      o.sample = group == "Samples";
      o.value = o.condition ? upper(localName(n)) : std::string(trimmed(n.child_value()));
      if (o.sample && !std::string_view(n.attribute("sampleCount").value()).empty()) o.value = "TIME_SERIES";
      log->observations.push_back(std::move(o));
      return true;
    }
  } walker;
  walker.log = &log;
  walker.lines = &lines;
  walker.source = &source;
  pugi::xml_node top = root;
  top.traverse(walker);
  return log;
}

MtcSampleTable mtconnectSampleTable(const MtcLog& log, double intervalS, const MtcDevices* devices) {
  if (!(intervalS > 0.0) || !std::isfinite(intervalS))
    throw OptionsError(ErrorContext{log.source, 0, 0, "--sample-interval"},
                       "an MTConnect log is resampled to a grid: give its interval (e.g. 10s, 1min)");
  MtcSampleTable out;
  out.intervalS = intervalS;
  // Which keys are scalar samples, in the order of their first observation.
  std::vector<std::string> keys;
  std::map<std::string, std::string> why;  // key -> reason it is not a column
  std::set<std::string> seen;
  for (const MtcObservation& o : log.observations) {
    if (!seen.insert(o.key).second) continue;
    keys.push_back(o.key);
  }
  std::map<std::string, bool> scalar;
  for (const MtcObservation& o : log.observations) {
    if (why.count(o.key)) continue;
    if (o.condition) {
      why[o.key] = "a condition";
      continue;
    }
    if (log.streams && !o.sample) {
      why[o.key] = "an event";
      continue;
    }
    if (!log.streams && devices) {
      const MtcDataItem* item = devices->find(o.key);
      if (!item) {
        why[o.key] = "not declared in " + devices->source;
        continue;
      }
      if (item->category != "SAMPLE") {
        why[o.key] = "a" + std::string(item->category == "EVENT" ? "n " : " ") +
                     (item->category.empty() ? "data item without a category" : upper(item->category));
        continue;
      }
    }
    if (o.value == "TIME_SERIES") {
      why[o.key] = "a time series";
      continue;
    }
    if (unavailable(o.value)) continue;
    if (!num::parseDouble(o.value)) {
      why[o.key] = "not a number ('" + o.value.substr(0, 30) + "', line " + std::to_string(o.line) + ")";
      continue;
    }
    scalar[o.key] = true;
  }
  std::vector<std::string> columns;
  for (const std::string& k : keys) {
    if (why.count(k))
      out.skipped.push_back(k + ": " + why[k]);
    else if (scalar.count(k))
      columns.push_back(k);
    else
      out.skipped.push_back(k + ": no value (only UNAVAILABLE)");
  }
  if (columns.empty())
    throw ValidationError(ErrorContext{log.source, 0, 0, {}},
                          "the MTConnect log has no sample with numbers (" +
                              std::to_string(out.skipped.size()) + " data items, none a numeric SAMPLE)");
  // The observations of the columns in time order (equal times in file order: the later one wins).
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < columns.size(); ++c) column[columns[c]] = c;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < log.observations.size(); ++i)
    if (column.count(log.observations[i].key)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return log.observations[a].timeS < log.observations[b].timeS;
  });
  const double t0 = log.observations[order.front()].timeS;
  const double t1 = log.observations[order.back()].timeS;
  const double span = (t1 - t0) / intervalS;
  if (span > 5e7)
    throw ValidationError(ErrorContext{log.source, 0, 0, "--sample-interval"},
                          "the log spans " + num::general((t1 - t0) / 3600.0, 4) +
                              " h: " + num::general(span, 3) + " rows at this interval; choose a longer one");
  const std::size_t rows = static_cast<std::size_t>(std::floor(span + 1e-9)) + 1;
  std::vector<std::string> header{"time_min"};
  header.insert(header.end(), columns.begin(), columns.end());
  std::vector<std::vector<std::string>> cells(rows, std::vector<std::string>(header.size()));
  std::vector<long> lines(rows, 0);
  std::vector<std::string> current(columns.size());
  std::size_t next = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const double t = t0 + static_cast<double>(r) * intervalS;
    while (next < order.size() && log.observations[order[next]].timeS <= t + 1e-9) {
      const MtcObservation& o = log.observations[order[next]];
      current[column[o.key]] =
          unavailable(o.value) ? std::string() : num::shortest(*num::parseDouble(o.value));
      lines[r] = o.line;
      ++next;
    }
    cells[r][0] = num::shortest(static_cast<double>(r) * intervalS / 60.0);
    for (std::size_t c = 0; c < columns.size(); ++c) cells[r][c + 1] = current[c];
  }
  out.startS = t0;
  out.table = CsvTable::fromCells(log.source, std::move(header), std::move(cells), std::move(lines));
  out.rule = "resampled every " + num::general(intervalS, 6) +
             " s from the first sample: each cell holds the last observation at or before its time "
             "(empty before the first one and while UNAVAILABLE)";
  return out;
}

MtcSampleTable readMtconnectSampleTable(const std::string& path, double intervalS) {
  const std::string text = readFile(path, 512u << 20);
  const std::string shown = displayPath(path);
  std::optional<MtcDevices> devices;
  if (const auto beside = devicesFileBeside(path)) devices = readMtconnectDevices(*beside);
  if (looksLikeMtconnectStreams(text))
    return mtconnectSampleTable(mtconnectStreamsFromText(text, shown), intervalS, nullptr);
  if (!looksLikeShdr(text))
    throw ParseError(ErrorContext{shown, 1, 0, {}},
                     "not an MTConnect log: neither SHDR lines (timestamp|key|value...) nor an "
                     "MTConnectStreams document");
  return mtconnectSampleTable(shdrFromText(text, shown, devices ? &*devices : nullptr), intervalS,
                              devices ? &*devices : nullptr);
}

}  // namespace metrofit
