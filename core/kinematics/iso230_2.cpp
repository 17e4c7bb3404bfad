#include "core/kinematics/iso230_2.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/run.h"
#include "core/io/file_io.h"

namespace metrofit {
namespace {

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// A whole positive number of at most 9 digits, or nullopt.
std::optional<long> wholeNumber(std::string_view s) {
  const std::string t = trim(s);
  if (t.empty() || t.size() > 9) return std::nullopt;
  long v = 0;
  for (char c : t) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return v;
}

/// The lines of a text (without '\r'), each with its 1-based number.
std::vector<std::pair<long, std::string>> linesOf(std::string_view text) {
  std::vector<std::pair<long, std::string>> out;
  long n = 0;
  std::size_t at = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") at = 3;
  while (at <= text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    out.emplace_back(++n, std::string(line));
    if (end == text.size()) break;
    at = end + 1;
  }
  return out;
}

bool isKeyValueLine(const std::string& line) {
  const std::size_t eq = line.find('=');
  if (eq == std::string::npos || eq == 0) return false;
  const std::string key = trim(std::string_view(line).substr(0, eq));
  if (key.empty()) return false;
  for (char c : key) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '[' || c == ']' || c == ',' ||
          c == ' '))
      return false;
  }
  return std::isalpha(static_cast<unsigned char>(key.front())) != 0;
}

double sampleStdDev(const std::vector<double>& v, double mean) {
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

/// num::fixed without a "-0.000": a value that rounds to zero is written as zero.
std::string fixedMm(double v, int decimals) {
  std::string s = num::fixed(v, decimals);
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

char axisLetter(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

/// The compensation on an equidistant grid from the first to the last target (m points): the targets
/// themselves when they are equally spaced, else linear interpolation.
struct Grid {
  double startMm = 0.0, stepMm = 0.0;
  std::vector<double> valueMm;
};

Grid equidistant(const PositioningResult& r) {
  const std::vector<double> c = compensationMm(r);
  const std::size_t m = r.targets.size();
  Grid g;
  g.startMm = r.targets.front().targetMm;
  g.stepMm = (r.targets.back().targetMm - g.startMm) / static_cast<double>(m - 1);
  g.valueMm.resize(m);
  std::size_t seg = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double p = k + 1 == m ? r.targets.back().targetMm : g.startMm + static_cast<double>(k) * g.stepMm;
    while (seg + 2 < m && r.targets[seg + 1].targetMm < p) ++seg;
    const double p0 = r.targets[seg].targetMm, p1 = r.targets[seg + 1].targetMm;
    const double t = std::clamp((p - p0) / (p1 - p0), 0.0, 1.0);
    g.valueMm[k] = c[seg] + t * (c[seg + 1] - c[seg]);
  }
  return g;
}

}  // namespace

bool isKeyValuePositioningTest(std::string_view text) {
  for (const auto& [n, line] : linesOf(text)) {
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    return isKeyValueLine(t);
  }
  return false;
}

PositioningTest positioningTestFromCsv(const CsvTable& t) {
  const std::size_t tgt = t.requireColumn("target_mm");
  const std::size_t dir = t.requireColumn("direction");
  const std::size_t cyc = t.requireColumn("cycle");
  const int dev = t.columnIndex("deviation_mm"), meas = t.columnIndex("measured_mm");
  if (dev < 0 && meas < 0) (void)t.requireColumn("deviation_mm");
  if (dev >= 0 && meas >= 0) {
    throw ValidationError(ErrorContext{t.source(), 0, 0, "measured_mm"},
                          "give the position once: deviation_mm or measured_mm, not both");
  }
  const std::size_t val = static_cast<std::size_t>(dev >= 0 ? dev : meas);
  t.requireRows(1);
  PositioningTest out;
  out.source = t.source();
  std::map<std::tuple<double, bool, long>, long> seen;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    PositioningSample s;
    s.line = t.lineOf(r);
    s.targetMm = t.number(r, tgt);
    const std::string d = trim(t.cell(r, dir));
    if (d == "+" || d == "+1")
      s.up = true;
    else if (d == "-" || d == "-1")
      s.up = false;
    else
      t.failAt(r, dir, "'" + t.cell(r, dir) + "' is not a direction (+ or -)");
    const std::optional<long> c = wholeNumber(t.cell(r, cyc));
    if (!c || *c < 1) t.failAt(r, cyc, "'" + t.cell(r, cyc) + "' is not a cycle number (1, 2, ...)");
    s.cycle = *c;
    const double v = t.number(r, val);
    s.deviationMm = meas >= 0 ? v - s.targetMm : v;
    if (!std::isfinite(s.deviationMm)) t.failAt(r, val, "the deviation is not finite");
    const auto [it, fresh] = seen.emplace(std::make_tuple(s.targetMm, s.up, s.cycle), s.line);
    if (!fresh) {
      t.failAt(r, cyc,
               "target " + num::shortest(s.targetMm) + " mm, direction " + (s.up ? "+" : "-") + ", cycle " +
                   std::to_string(s.cycle) + " is given twice (first on line " + std::to_string(it->second) +
                   ")");
    }
    out.samples.push_back(s);
  }
  return out;
}

PositioningTest positioningTestFromKeyValue(std::string_view text, const std::string& source) {
  struct Value {
    long line;
    double v;
  };
  std::map<long, Value> target;
  std::map<std::pair<long, long>, Value> fwd, bwd;
  std::optional<long> cycles, positions;
  long cyclesLine = 0, positionsLine = 0;
  double unitScale = 1.0;
  auto fail = [&](long line, const std::string& key, const std::string& what) -> void {
    throw ParseError(ErrorContext{source, line, 0, key}, what);
  };
  for (const auto& [n, raw] : linesOf(text)) {
    const std::string line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    if (!isKeyValueLine(line)) fail(n, {}, "'" + line + "' is not a KEY=value line");
    const std::size_t eq = line.find('=');
    std::string key = trim(std::string_view(line).substr(0, eq));
    const std::string value = trim(std::string_view(line).substr(eq + 1));
    std::string name = upper(key), index;
    if (const std::size_t br = name.find('['); br != std::string::npos) {
      if (name.back() != ']') fail(n, key, "the index of '" + key + "' is not closed with ']'");
      index = name.substr(br + 1, name.size() - br - 2);
      name = trim(name.substr(0, br));
    }
    auto number = [&]() {
      const std::optional<double> v = num::parseDouble(value);
      if (!v || !std::isfinite(*v)) fail(n, key, "'" + value + "' is not a number");
      return *v;
    };
    auto indices = [&](std::size_t count) {
      std::vector<long> out;
      std::size_t at = 0;
      while (true) {
        const std::size_t comma = index.find(',', at);
        const std::optional<long> v = wholeNumber(
            std::string_view(index).substr(at, comma == std::string::npos ? index.npos : comma - at));
        if (!v || *v < 1) break;
        out.push_back(*v);
        if (comma == std::string::npos) break;
        at = comma + 1;
      }
      if (out.size() != count) {
        fail(n, key,
             "'" + key + "' needs " + (count == 1 ? "one index [i]" : "two indices [i,j]") +
                 " counted from 1");
      }
      return out;
    };
    if (name == "UNIT") {
      const std::string u = upper(value);
      if (u == "MM")
        unitScale = 1.0;
      else if (u == "UM" || u == "MICRON" || value == "\xC2\xB5m")
        unitScale = 1e-3;
      else
        fail(n, key, "unit '" + value + "' is not mm or um");
    } else if (name == "CYCLES" || name == "POSITIONS") {
      const std::optional<long> v = wholeNumber(value);
      if (!v || *v < 1) fail(n, key, "'" + value + "' is not a positive whole number");
      (name == "CYCLES" ? cycles : positions) = *v;
      (name == "CYCLES" ? cyclesLine : positionsLine) = n;
    } else if (name == "TGT_DATA") {
      const long i = indices(1)[0];
      if (target.count(i))
        fail(n, key,
             "'" + key + "' is given twice (first on line " + std::to_string(target.at(i).line) + ")");
      target[i] = {n, number()};
    } else if (name == "REF_DATA_FWD" || name == "REF_DATA_BWD") {
      const std::vector<long> ij = indices(2);
      auto& map = name == "REF_DATA_FWD" ? fwd : bwd;
      const auto k = std::make_pair(ij[0], ij[1]);
      if (map.count(k))
        fail(n, key, "'" + key + "' is given twice (first on line " + std::to_string(map.at(k).line) + ")");
      map[k] = {n, number()};
    }
  }
  if (target.empty())
    throw ValidationError(ErrorContext{source, 0, 0, "TGT_DATA"}, "no target position TGT_DATA[i]");
  const long m = positions.value_or(static_cast<long>(target.size()));
  for (long i = 1; i <= m; ++i) {
    if (!target.count(i)) {
      throw ValidationError(
          ErrorContext{source, positionsLine, 0, "TGT_DATA[" + std::to_string(i) + "]"},
          "POSITIONS is " + std::to_string(m) + " but target " + std::to_string(i) + " has no TGT_DATA");
    }
  }
  for (const auto& [i, v] : target) {
    if (i > m) {
      throw ValidationError(ErrorContext{source, v.line, 0, "TGT_DATA[" + std::to_string(i) + "]"},
                            "target " + std::to_string(i) + " is beyond POSITIONS " + std::to_string(m));
    }
  }
  long n = 0;
  for (const auto& [k, v] : fwd) n = std::max(n, k.second);
  for (const auto& [k, v] : bwd) n = std::max(n, k.second);
  n = cycles.value_or(n);
  PositioningTest out;
  out.source = source;
  for (const bool up : {true, false}) {
    const auto& map = up ? fwd : bwd;
    const std::string name = up ? "REF_DATA_FWD" : "REF_DATA_BWD";
    for (const auto& [k, v] : map) {
      if (!target.count(k.first) || k.second > n) {
        throw ValidationError(
            ErrorContext{source, v.line, 0,
                         name + "[" + std::to_string(k.first) + "," + std::to_string(k.second) + "]"},
            "beyond POSITIONS " + std::to_string(m) + " / CYCLES " + std::to_string(n));
      }
    }
    for (long i = 1; i <= m; ++i) {
      for (long j = 1; j <= n; ++j) {
        const auto it = map.find({i, j});
        if (it == map.end()) {
          throw ValidationError(
              ErrorContext{source, cycles ? cyclesLine : 0, 0,
                           name + "[" + std::to_string(i) + "," + std::to_string(j) + "]"},
              "missing: CYCLES is " + std::to_string(n) + " and POSITIONS " + std::to_string(m));
        }
        PositioningSample s;
        s.targetMm = target.at(i).v * unitScale;
        s.up = up;
        s.cycle = j;
        s.deviationMm = it->second.v * unitScale - s.targetMm;
        s.line = it->second.line;
        out.samples.push_back(s);
      }
    }
  }
  return out;
}

PositioningTest readPositioningTest(const std::string& path, const CsvReadOptions& csv) {
  const std::string text = readFile(path);
  const std::string source = path == "-" ? "<stdin>" : path;
  if (isKeyValuePositioningTest(text)) return positioningTestFromKeyValue(text, source);
  return positioningTestFromCsv(parseCsv(text, source, csv));
}

PositioningResult evaluateIso230_2(const PositioningTest& test) {
  if (test.samples.empty())
    throw ValidationError(ErrorContext{test.source, 0, 0, {}}, "the positioning test has no sample");
  struct Acc {
    std::vector<double> up, down;
    long firstLine = 0;
  };
  std::map<double, Acc> byTarget;
  for (const PositioningSample& s : test.samples) {
    Acc& a = byTarget[s.targetMm];
    if (a.firstLine == 0) a.firstLine = s.line;
    (s.up ? a.up : a.down).push_back(s.deviationMm);
  }
  PositioningResult r;
  r.source = test.source;
  for (const auto& [target, a] : byTarget) {
    for (const bool up : {true, false}) {
      const std::size_t k = (up ? a.up : a.down).size();
      if (k < 2) {
        throw ValidationError(ErrorContext{test.source, a.firstLine, 0, "direction"},
                              "target " + num::shortest(target) + " mm has " + std::to_string(k) +
                                  " approach" + (k == 1 ? "" : "es") + " in the " +
                                  (up ? "positive (+)" : "negative (-)") +
                                  " direction: ISO 230-2 needs at least 2 (5 cycles) from each direction");
      }
    }
    PositioningTarget p;
    p.targetMm = target;
    p.nUp = a.up.size();
    p.nDown = a.down.size();
    auto mean = [](const std::vector<double>& v) {
      double s = 0.0;
      for (double x : v) s += x;
      return s / static_cast<double>(v.size());
    };
    p.meanUpMm = mean(a.up);
    p.meanDownMm = mean(a.down);
    p.sUpMm = sampleStdDev(a.up, p.meanUpMm);
    p.sDownMm = sampleStdDev(a.down, p.meanDownMm);
    p.reversalMm = p.meanUpMm - p.meanDownMm;
    r.targets.push_back(p);
  }
  const double inf = std::numeric_limits<double>::infinity();
  double maxUp = -inf, minUp = inf, maxDown = -inf, minDown = inf, maxMean = -inf, minMean = inf;
  double aUpHi = -inf, aUpLo = inf, aDownHi = -inf, aDownLo = inf, bSum = 0.0;
  for (const PositioningTarget& p : r.targets) {
    r.B = std::max(r.B, std::abs(p.reversalMm));
    bSum += p.reversalMm;
    const double rUp = 4.0 * p.sUpMm, rDown = 4.0 * p.sDownMm;
    r.Rup = std::max(r.Rup, rUp);
    r.Rdown = std::max(r.Rdown, rDown);
    r.R = std::max({r.R, 2.0 * p.sUpMm + 2.0 * p.sDownMm + std::abs(p.reversalMm), rUp, rDown});
    maxUp = std::max(maxUp, p.meanUpMm);
    minUp = std::min(minUp, p.meanUpMm);
    maxDown = std::max(maxDown, p.meanDownMm);
    minDown = std::min(minDown, p.meanDownMm);
    maxMean = std::max(maxMean, p.meanMm());
    minMean = std::min(minMean, p.meanMm());
    aUpHi = std::max(aUpHi, p.meanUpMm + 2.0 * p.sUpMm);
    aUpLo = std::min(aUpLo, p.meanUpMm - 2.0 * p.sUpMm);
    aDownHi = std::max(aDownHi, p.meanDownMm + 2.0 * p.sDownMm);
    aDownLo = std::min(aDownLo, p.meanDownMm - 2.0 * p.sDownMm);
  }
  r.Bmean = bSum / static_cast<double>(r.targets.size());
  r.Eup = maxUp - minUp;
  r.Edown = maxDown - minDown;
  r.E = std::max(maxUp, maxDown) - std::min(minUp, minDown);
  r.M = maxMean - minMean;
  r.Aup = aUpHi - aUpLo;
  r.Adown = aDownHi - aDownLo;
  r.A = std::max(aUpHi, aDownHi) - std::min(aUpLo, aDownLo);
  return r;
}

nlohmann::json iso230_2ToJson(const PositioningResult& r) {
  nlohmann::json j;
  j["B_mm"] = r.B;
  j["B_mean_mm"] = r.Bmean;
  j["E_up_mm"] = r.Eup;
  j["E_down_mm"] = r.Edown;
  j["E_mm"] = r.E;
  j["M_mm"] = r.M;
  j["R_up_mm"] = r.Rup;
  j["R_down_mm"] = r.Rdown;
  j["R_mm"] = r.R;
  j["A_up_mm"] = r.Aup;
  j["A_down_mm"] = r.Adown;
  j["A_mm"] = r.A;
  nlohmann::json targets = nlohmann::json::array();
  for (const PositioningTarget& p : r.targets) {
    targets.push_back({{"target_mm", p.targetMm},
                       {"x_up_mm", p.meanUpMm},
                       {"x_down_mm", p.meanDownMm},
                       {"s_up_mm", p.sUpMm},
                       {"s_down_mm", p.sDownMm},
                       {"B_mm", p.reversalMm}});
  }
  j["targets"] = std::move(targets);
  return j;
}

PitchTableFormat parsePitchTableFormat(std::string_view text, const std::string& option) {
  if (text == "fanuc") return PitchTableFormat::Fanuc;
  if (text == "siemens") return PitchTableFormat::Siemens;
  if (text == "heidenhain") return PitchTableFormat::Heidenhain;
  if (text == "csv") return PitchTableFormat::Csv;
  throw OptionsError(
      ErrorContext{{}, 0, 0, option},
      "'" + std::string(text) + "' is not a compensation table form (fanuc, siemens, heidenhain, csv)");
}

bool PitchTableOptions::isValid(std::string* why) const {
  auto no = [&](std::string w) {
    if (why) *why = std::move(w);
    return false;
  };
  if (std::string("XYZUVWABC").find(axisLetter(axis)) == std::string::npos || axis == 0)
    return no(std::string("axis must be one of X, Y, Z, U, V, W, A, B, C, got '") + axis + "'");
  if (!(fanucDetectionUnitMm > 0.0) || !std::isfinite(fanucDetectionUnitMm))
    return no("fanucDetectionUnitMm must be positive, got " + num::shortest(fanucDetectionUnitMm));
  if (fanucReferenceNumber < 0 || fanucReferenceNumber > 1023)
    return no("fanucReferenceNumber must be in 0..1023, got " + std::to_string(fanucReferenceNumber));
  return true;
}

std::vector<double> compensationMm(const PositioningResult& r) {
  std::vector<double> c;
  c.reserve(r.targets.size());
  for (const PositioningTarget& p : r.targets) c.push_back(p.meanMm() == 0.0 ? 0.0 : -p.meanMm());
  return c;
}

std::string pitchCompensationTable(const PositioningResult& r, PitchTableFormat format,
                                   const PitchTableOptions& o) {
  requireValid(o, "pitch compensation table options");
  const std::size_t m = r.targets.size();
  if (format == PitchTableFormat::Csv) {
    CsvWriter w;
    w.row({"target_mm", "compensation_mm"});
    const std::vector<double> c = compensationMm(r);
    for (std::size_t i = 0; i < m; ++i) w.row({num::shortest(r.targets[i].targetMm), fixedMm(c[i], 6)});
    return w.text();
  }
  if (m < 2) {
    throw ValidationError(
        ErrorContext{r.source, 0, 0, "target_mm"},
        "a compensation table needs at least 2 targets (an interval), got " + std::to_string(m));
  }
  const Grid g = equidistant(r);
  const char axis = axisLetter(o.axis);
  std::string out;
  if (format == PitchTableFormat::Fanuc) {
    const double u = o.fanucDetectionUnitMm;
    const long ref = o.fanucReferenceNumber;
    const long last = ref + static_cast<long>(m) - 1;
    if (last > 1023) {
      throw ValidationError(
          ErrorContext{r.source, 0, 0, "target_mm"},
          "the Fanuc table would end at compensation point " + std::to_string(last) + " (at most 1023)");
    }
    const std::string axisNo = std::to_string(std::string("XYZUVWABC").find(axis) + 1);
    const long interval = std::lround(g.stepMm / u);
    out += "%\n";
    out += "N3620A" + axisNo + "P" + std::to_string(ref) + "\n";
    out += "N3621A" + axisNo + "P" + std::to_string(ref) + "\n";
    out += "N3622A" + axisNo + "P" + std::to_string(last) + "\n";
    out += "N3623A" + axisNo + "P1\n";
    out += "N3624A" + axisNo + "P" + std::to_string(interval) + "\n";
    long previous = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const long absolute = std::lround((g.valueMm[k] - g.valueMm[0]) / u);
      out += "N" + std::to_string(10000 + ref + static_cast<long>(k)) + "P" +
             std::to_string(k == 0 ? 0 : absolute - previous) + "\n";
      previous = absolute;
    }
    out += "%\n";
  } else if (format == PitchTableFormat::Siemens) {
    const std::string ax = std::string(1, axis) + "1";
    out += "%_N_AX_EEC_INI\n";
    out += "CHANDATA(1)\n";
    out += "; ISO 230-2 pitch error compensation (metrofit): minus the mean bidirectional deviation, mm\n";
    for (std::size_t k = 0; k < m; ++k) {
      out += "$AA_ENC_COMP[0," + std::to_string(k) + "," + ax + "]=" + fixedMm(g.valueMm[k], 6) + "\n";
    }
    out += "$AA_ENC_COMP_STEP[0," + ax + "]=" + fixedMm(g.stepMm, 6) + "\n";
    out += "$AA_ENC_COMP_MIN[0," + ax + "]=" + fixedMm(g.startMm, 6) + "\n";
    out += "$AA_ENC_COMP_MAX[0," + ax + "]=" + fixedMm(g.startMm + static_cast<double>(m - 1) * g.stepMm, 6) +
           "\n";
    out += "$AA_ENC_COMP_IS_MODULO[0," + ax + "]=0\n";
    out += "M17\n";
  } else {
    out += std::string("BEGIN ") + axis + ".COM MM\n";
    out += cformat("%-6s %-14s %s\n", "NR", "AXISPOS", std::string(1, axis).c_str());
    for (std::size_t k = 0; k < m; ++k) {
      const double p = g.startMm + static_cast<double>(k) * g.stepMm;
      out += cformat("%-6zu %-14s %s\n", k, num::fixedSigned(p, 4).c_str(),
                     num::fixedSigned(g.valueMm[k], 5).c_str());
    }
    out += "[END]\n";
  }
  return out;
}

}  // namespace metrofit
