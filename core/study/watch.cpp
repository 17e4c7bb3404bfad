#include "core/study/watch.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <system_error>
#include <thread>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/diagnose/setup_diagnosis.h"
#include "core/io/file_io.h"
#include "core/project/datasets.h"
#include "core/project/import_guess.h"
#include "core/project/project.h"
#include "core/setup/exact.h"
#include "core/setup/objective.h"
#include "core/spc/spc.h"
#include "core/study/setup_study.h"

namespace metrofit {
namespace fs = std::filesystem;

namespace {

std::string fnv1a64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  static const char* hex = "0123456789abcdef";
  for (int i = 15; i >= 0; --i) {
    buf[i] = hex[h & 0xf];
    h >>= 4;
  }
  buf[16] = 0;
  return buf;
}

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

bool endsWith(const std::string& s, const char* suffix) {
  const std::size_t n = std::strlen(suffix);
  if (s.size() < n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - n + i])) != suffix[i]) return false;
  return true;
}

/// A writer's temporary name or a hidden file (see the header comment).
bool ignoredName(const std::string& name) {
  if (name.empty() || name[0] == '.' || name.back() == '~') return true;
  for (const char* s : {".tmp", ".part", ".partial", ".crdownload", ".watch.jsonl", ".error.txt"})
    if (endsWith(name, s)) return true;
  return false;
}

std::int64_t mtimeNs(const fs::file_time_type& t) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

/// Rounds away binary noise for the JSON (as `setup` does).
double clean(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0.0 ? 0.0 : r;
}

nlohmann::json measurementsToJson(const setup::Measurements& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : m.rows)
    rows.push_back({r.part, r.timeMin, r.dimension, r.deviationMm, r.source, r.line});
  return {{"sources", m.sources},
          {"parts", m.parts},
          {"rows", std::move(rows)},
          {"deviation_mm", m.deviationMm},
          {"samples", m.samples}};
}

setup::Measurements measurementsFromJson(const nlohmann::json& j, const setup::Model& model) {
  setup::Measurements m;
  m.sources = j.at("sources").get<std::vector<std::string>>();
  m.parts = j.at("parts").get<std::vector<std::string>>();
  for (const auto& r : j.at("rows")) {
    setup::Measurements::Row row;
    row.part = r.at(0).get<std::string>();
    row.timeMin = r.at(1).get<double>();
    row.dimension = r.at(2).get<std::size_t>();
    row.deviationMm = r.at(3).get<double>();
    row.source = r.at(4).get<std::string>();
    row.line = r.at(5).get<long>();
    if (row.dimension >= model.dimensions.size()) throw std::out_of_range("dimension index");
    m.rows.push_back(std::move(row));
  }
  m.deviationMm = j.at("deviation_mm").get<std::vector<double>>();
  m.samples = j.at("samples").get<std::vector<int>>();
  if (m.deviationMm.size() != model.dimensions.size() || m.samples.size() != model.dimensions.size())
    throw std::out_of_range("dimensions");
  return m;
}

/// One line: the first line of an exception's message.
std::string oneLine(const std::string& s) {
  std::string out = s.substr(0, s.find('\n'));
  return out.empty() ? std::string("unreadable file") : out;
}

}  // namespace

bool WatchOptions::isValid(std::string* why) const {
  auto fail = [why](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (projectPath.empty()) return fail("--project: a project file is required");
  if (folder.empty()) return fail("DIR: the watched folder is required");
  if (pollMs < 10 || pollMs > 60000)
    return fail("--poll-ms: must be 10..60000, got " + std::to_string(pollMs));
  if (diagnoseEvery < 1) return fail("--diagnose-every: must be >= 1, got " + std::to_string(diagnoseEvery));
  if (!(coverageFactor > 0.0) || !std::isfinite(coverageFactor)) return fail("coverage factor must be > 0");
  return true;
}

nlohmann::json WatchEvent::toJson() const {
  nlohmann::json j;
  j["file"] = file;
  j["kind"] = kind.empty() ? nlohmann::json(nullptr) : nlohmann::json(kind);
  std::string joined;
  for (const auto& p : parts) joined += (joined.empty() ? "" : ", ") + p;
  j["part"] = parts.empty() ? nlohmann::json(nullptr) : nlohmann::json(joined);
  j["parts"] = parts;
  j["error"] = error.empty() ? nlohmann::json(nullptr) : nlohmann::json(error);
  j["seconds"] = std::round(seconds * 1e4) / 1e4;
  if (!error.empty()) {
    j["in_control"] = nullptr;
    j["correction"] = nullptr;
    j["residual_white"] = nullptr;
    j["rejected_to"] = rejectedTo;
    j["series_parts"] = seriesParts;
    return j;
  }
  j["series_parts"] = seriesParts;
  j["in_control"] = inControl ? nlohmann::json(*inControl) : nlohmann::json(nullptr);
  j["out_of_control"] = outOfControl;
  j["significant"] = significant;
  nlohmann::json c = nlohmann::json::object();
  for (const auto& [id, v] : correction) c[id] = clean(v);
  j["correction"] = std::move(c);
  j["changed"] = changed;
  j["f1_before_mm"] = clean(f1BeforeMm);
  j["f1_mm"] = clean(f1Mm);
  j["released"] = released;
  j["gate"] = gate;
  j["offsets"] = offsetsFile.empty() ? nlohmann::json(nullptr) : nlohmann::json(offsetsFile);
  j["residual_white"] = residualWhite ? nlohmann::json(*residualWhite) : nlohmann::json(nullptr);
  j["residual"] = residual;
  return j;
}

std::string WatchSession::journalPathFor(const std::string& projectPath) {
  const fs::path p(projectPath);
  return joinPath(parentFolder(projectPath), p.stem().string() + ".watch.jsonl");
}

std::string WatchSession::offsetsFileName(setup::ControllerFormat control) {
  switch (control) {
    case setup::ControllerFormat::Fanuc:
      return "offsets.nc";
    case setup::ControllerFormat::Heidenhain:
      return "offsets.h";
    case setup::ControllerFormat::Siemens:
      return "offsets.spf";
    case setup::ControllerFormat::Csv:
      break;
  }
  return "offsets.csv";
}

WatchSession::WatchSession(WatchOptions options) : options_(std::move(options)) {
  std::string why;
  if (!options_.isValid(&why)) throw OptionsError(ErrorContext{}, why);
  std::error_code ec;
  if (!fs::is_directory(options_.folder, ec))
    throw FileError(ErrorContext{options_.folder, 0, 0, {}}, "the watched folder does not exist");
  const Project project = loadProject(options_.projectPath);
  const SetupStudyFiles files = setupStudyFiles(project, options_.projectPath);
  if (files.modelPath.empty())
    throw ValidationError(ErrorContext{options_.projectPath, 0, 0, "datasets"},
                          "the project has no setup model (a setup_model dataset) to correct against");
  model_ = setup::readModel(files.modelPath);
  if (options_.outFolder.empty())
    options_.outFolder = joinPath(parentFolder(options_.projectPath), "offsets");
  fs::create_directories(options_.outFolder, ec);
  if (ec || !fs::is_directory(options_.outFolder))
    throw FileError(ErrorContext{options_.outFolder, 0, 0, {}}, "cannot create the offsets folder");
  offsetsPath_ = joinPath(options_.outFolder, offsetsFileName(options_.control));
  journalPath_ = journalPathFor(options_.projectPath);
  loadJournal();
}

WatchSession::~WatchSession() {
  setup::releaseExactSolverThread();
}

void WatchSession::loadJournal() {
  std::error_code ec;
  if (!fs::exists(journalPath_, ec)) return;
  std::string text = readFile(journalPath_);
  // A line cut short by a kill has no newline: drop it (its file is processed again).
  const std::size_t end = text.rfind('\n');
  const std::size_t keep = end == std::string::npos ? 0 : end + 1;
  if (keep != text.size()) {
    fs::resize_file(journalPath_, keep, ec);
    if (ec)
      throw FileError(ErrorContext{journalPath_, 0, 0, {}}, "cannot drop the cut line: " + ec.message());
    text.resize(keep);
  }
  long lineNo = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++lineNo;
    if (line.empty()) continue;
    try {
      const nlohmann::json j = nlohmann::json::parse(line);
      Done d;
      d.size = j.at("size").get<std::uintmax_t>();
      d.mtimeNs = j.at("mtime_ns").get<std::int64_t>();
      d.hash = j.at("hash").get<std::string>();
      d.rejected = j.at("status").get<std::string>() == "rejected";
      if (!d.rejected) append(measurementsFromJson(j.at("measurements"), model_));
      done_.emplace(j.at("file").get<std::string>(), std::move(d));
    } catch (const std::exception& e) {
      throw ValidationError(ErrorContext{journalPath_, lineNo, 0, {}},
                            std::string("not a watch journal line (") + e.what() +
                                "); was it written for another setup model?");
    }
  }
  if (seriesFiles_ > 0 &&
      std::all_of(series_.samples.begin(), series_.samples.end(), [](int n) { return n > 0; }))
    lastCorrection_ = setup::solveExact(setup::SetupInstance(model_, series_.deviationMm)).x;
}

void WatchSession::checkNew(const setup::Measurements& m) const {
  for (const auto& r : m.rows) {
    const auto it = measured_.find(std::make_pair(r.part, r.dimension));
    if (it == measured_.end()) continue;
    throw ValidationError(ErrorContext{r.source, r.line, 0, "part"},
                          "part '" + r.part + "', dimension '" + model_.dimensions[r.dimension].id +
                              "' is measured twice (first in " + it->second.first + " line " +
                              std::to_string(it->second.second) + ")");
  }
}

void WatchSession::append(setup::Measurements m) {
  const std::size_t n = model_.dimensions.size();
  if (sumMm_.empty()) {
    sumMm_.assign(n, 0.0);
    chartValues_.assign(n, {});
    series_.samples.assign(n, 0);
    series_.deviationMm.assign(n, 0.0);
  }
  for (auto& s : m.sources) series_.sources.push_back(std::move(s));
  for (const auto& p : m.parts)
    if (std::find(series_.parts.begin(), series_.parts.end(), p) == series_.parts.end())
      series_.parts.push_back(p);
  for (auto& r : m.rows) {
    measured_.emplace(std::make_pair(r.part, r.dimension), std::make_pair(r.source, r.line));
    sumMm_[r.dimension] += r.deviationMm;
    ++series_.samples[r.dimension];
    chartValues_[r.dimension].push_back(r.deviationMm);
    series_.rows.push_back(std::move(r));
  }
  for (std::size_t q = 0; q < n; ++q)
    series_.deviationMm[q] = series_.samples[q] > 0 ? sumMm_[q] / series_.samples[q] : 0.0;
  ++seriesFiles_;
}

void WatchSession::appendJournal(const std::string& line) {
  const int fd = ::open(journalPath_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw FileError(ErrorContext{journalPath_, 0, 0, {}},
                    std::string("cannot open: ") + std::strerror(errno));
  const std::string text = line + "\n";
  std::size_t off = 0;
  while (off < text.size()) {
    const ssize_t n = ::write(fd, text.data() + off, text.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = errno;
      ::close(fd);
      throw FileError(ErrorContext{journalPath_, 0, 0, {}},
                      std::string("cannot write: ") + std::strerror(err));
    }
    off += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    throw FileError(ErrorContext{journalPath_, 0, 0, {}}, std::string("cannot fsync: ") + std::strerror(err));
  }
  ::close(fd);
}

bool WatchSession::journaled(const std::string& name, std::uintmax_t size, std::int64_t mtime) const {
  const auto [b, e] = done_.equal_range(name);
  for (auto it = b; it != e; ++it)
    if (it->second.size == size && it->second.mtimeNs == mtime) return true;
  return false;
}

std::vector<std::string> WatchSession::poll() {
  ++polls_;
  struct Candidate {
    std::string name;
    std::int64_t mtime;
  };
  std::vector<Candidate> ready;
  std::map<std::string, Seen> now;
  std::error_code ec;
  for (fs::directory_iterator it(options_.folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code fe;
    if (!it->is_regular_file(fe) || fe) continue;
    const std::string name = it->path().filename().string();
    if (ignoredName(name)) continue;
    const std::uintmax_t size = it->file_size(fe);
    if (fe) continue;
    const auto t = it->last_write_time(fe);
    if (fe) continue;
    const Seen s{size, mtimeNs(t)};
    if (journaled(name, s.size, s.mtimeNs)) {
      // A reject journaled but not yet moved (killed in between): finish it.
      const auto [b, e] = done_.equal_range(name);
      for (auto d = b; d != e; ++d) {
        if (d->second.rejected && d->second.size == s.size && d->second.mtimeNs == s.mtimeNs) {
          const fs::path dir = fs::path(options_.folder) / "rejected";
          fs::create_directories(dir, fe);
          fs::rename(it->path(), dir / name, fe);
          break;
        }
      }
      continue;
    }
    now[name] = s;
    const auto prev = seen_.find(name);
    if (prev != seen_.end() && prev->second.size == s.size && prev->second.mtimeNs == s.mtimeNs)
      ready.push_back({name, s.mtimeNs});
  }
  seen_ = std::move(now);
  std::sort(ready.begin(), ready.end(), [](const Candidate& a, const Candidate& b) {
    return a.mtime != b.mtime ? a.mtime < b.mtime : a.name < b.name;
  });
  std::vector<std::string> names;
  for (auto& c : ready) names.push_back(std::move(c.name));
  return names;
}

WatchEvent WatchSession::reject(WatchEvent e, const std::string& name, std::uintmax_t size,
                                std::int64_t mtime, const std::string& hash, const std::string& error) {
  e.error = oneLine(error);
  e.seriesParts = series_.parts.size();
  const fs::path dir = fs::path(options_.folder) / "rejected";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(ErrorContext{dir.string(), 0, 0, {}}, "cannot create: " + ec.message());
  // Order: the error beside its future place, the journal line, then the move (a kill between the
  // last two is finished by the next poll).
  writeFileAtomic((dir / (name + ".error.txt")).string(), e.error + "\n");
  nlohmann::json j{
      {"v", 1},           {"file", name},         {"size", size},   {"mtime_ns", mtime},
      {"hash", hash},     {"status", "rejected"}, {"kind", e.kind}, {"parts", nlohmann::json::array()},
      {"time", utcNow()}, {"error", e.error}};
  appendJournal(j.dump());
  done_.emplace(name, Done{size, mtime, hash, true});
  fs::rename(fs::path(options_.folder) / name, dir / name, ec);
  e.rejectedTo = (dir / name).string();
  return e;
}

WatchEvent WatchSession::process(const std::string& name, bool runDiagnosis) {
  const auto t0 = std::chrono::steady_clock::now();
  WatchEvent e;
  e.file = name;
  const std::string path = (fs::path(options_.folder) / name).string();
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  const std::int64_t mtime = ec ? 0 : mtimeNs(fs::last_write_time(path, ec));
  if (ec) {
    e.error = name + ": vanished before it was read";
    return e;
  }
  std::string text, hash;
  setup::Measurements m;
  try {
    text = readFile(path, 256u << 20);
    hash = fnv1a64(text);
    // The same content under the same name (touched, copied again): taken already.
    const auto [b, en] = done_.equal_range(name);
    for (auto it = b; it != en; ++it) {
      if (it->second.hash == hash) {
        e.error.clear();
        e.kind.clear();
        e.gate = "already in the journal (same content)";
        done_.emplace(name, Done{size, mtime, hash, it->second.rejected});
        e.file.clear();  // nothing to report
        return e;
      }
    }
    e.kind = guessDatasetKind(name, text);
    if (!datasetKindServes(dataset_kind::kCmmReport, datasetKindFromName(e.kind)))
      throw ValidationError(
          ErrorContext{name, 0, 0, {}},
          "a " + e.kind +
              " file is not a report of measured dimensions; the watch loop feeds the setup "
              "study (CMM report CSV, DMIS, OGP / PC-DMIS text, DFQ, Calypso _chr, QIF)");
    m = setup::readMeasurements({path}, model_);
    for (auto& r : m.rows) r.source = name;
    for (auto& s : m.sources) s = name;
  } catch (const std::exception& ex) {
    e = reject(std::move(e), name, size, mtime, hash.empty() ? fnv1a64(text) : hash, ex.what());
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return e;
  }

  try {
    checkNew(m);
  } catch (const std::exception& ex) {
    e = reject(std::move(e), name, size, mtime, hash, ex.what());
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return e;
  }
  e.parts = m.parts;
  const nlohmann::json measurementsJson = measurementsToJson(m);
  append(std::move(m));  // nothing below rejects the file
  const setup::Measurements& merged = series_;
  e.seriesParts = merged.parts.size();

  // The correction: the exact optimum on the series (as `setup --method exact`), once every
  // dimension has a measurement (a DMIS series of a multi-part fixture may take several files).
  std::string unmeasured;
  for (std::size_t q = 0; q < merged.samples.size() && unmeasured.empty(); ++q)
    if (merged.samples[q] == 0) unmeasured = model_.dimensions[q].id;
  std::vector<double> x;
  if (unmeasured.empty()) {
    const setup::SetupInstance inst(model_, merged.deviationMm);
    const setup::ExactResult exact = setup::solveExact(inst);
    x = exact.x;
    for (std::size_t i = 0; i < exact.x.size(); ++i) {
      e.correction.emplace_back(inst.datumIds()[i], exact.x[i]);
      if (lastCorrection_.size() != exact.x.size() || std::abs(lastCorrection_[i] - exact.x[i]) > 1e-12)
        e.changed.push_back(inst.datumIds()[i]);
    }
    e.f1BeforeMm = inst.f1Before();
    e.f1Mm = exact.score.f1;
  }

  // SPC per dimension: individuals of the deviation in arrival order.
  const std::vector<std::vector<double>>& perDim = chartValues_;
  bool allCharted = true, allIn = true;
  for (std::size_t q = 0; q < model_.dimensions.size(); ++q) {
    const setup::Dimension& d = model_.dimensions[q];
    SpcOptions so;
    so.subgroupSize = 1;
    so.lsl = d.lower;
    so.usl = d.upper;
    so.nominal = 0.0;
    so.coverageFactor = options_.coverageFactor;
    so.minCorrection = model_.stepMm;
    try {
      const SpcResult r = analyseSpc(perDim[q], so, ErrorContext{{}, 0, 0, d.id});
      if (!r.chart.inControl()) {
        allIn = false;
        e.outOfControl.push_back(d.id);
      }
      if (r.decision.apply) e.significant.push_back(d.id);
    } catch (const InputError&) {
      allCharted = false;  // fewer than 2 values or no variation yet
    }
  }
  if (!e.outOfControl.empty())
    e.inControl = false;
  else if (allCharted && allIn)
    e.inControl = true;

  // The gate.
  if (!unmeasured.empty()) {
    e.gate = "held: dimension " + unmeasured + " has no measurement yet";
  } else if (e.inControl == false) {
    e.gate = "held: out of control (" + std::to_string(e.outOfControl.size()) + " dimension(s), first " +
             e.outOfControl.front() + "): special causes first";
  } else if (!e.inControl) {
    e.gate = "held: too few parts to chart every dimension (" + std::to_string(merged.parts.size()) + ")";
  } else if (e.significant.empty()) {
    e.gate = "held: no dimension has a significant systematic deviation (random scatter only)";
  } else {
    e.released = true;
    e.gate = "released: in control, " + std::to_string(e.significant.size()) +
             " dimension(s) with a significant systematic deviation";
  }
  if (e.released) {
    const std::string textOut = setup::exportCorrections(model_, x, options_.control, setup::ExportOptions{});
    writeFileAtomic(offsetsPath_, textOut);
    e.offsetsFile = offsetsPath_;
  }

  // The diagnosis's residual check.
  if (runDiagnosis) {
    try {
      const diagnose::Diagnosis dg = diagnose::diagnoseSetup(model_, merged);
      if (dg.residualCheck) {
        e.residualWhite = dg.residualCheck->white;
        e.residual = dg.residualCheck->summary;
      }
      for (const auto* c : dg.accepted()) e.residual += (e.residual.empty() ? "" : "; accepted ") + c->name;
    } catch (const InputError& ex) {
      e.residual = oneLine(ex.what());
    }
  } else {
    e.residual = "not checked for this file (--diagnose-every)";
  }

  // The journal line last: the outputs above are on disk.
  nlohmann::json j{{"v", 1},
                   {"file", name},
                   {"size", size},
                   {"mtime_ns", mtime},
                   {"hash", hash},
                   {"status", "accepted"},
                   {"kind", e.kind},
                   {"parts", e.parts},
                   {"time", utcNow()},
                   {"released", e.released},
                   {"measurements", measurementsJson}};
  appendJournal(j.dump());
  done_.emplace(name, Done{size, mtime, hash, false});
  if (!x.empty()) lastCorrection_ = x;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

std::size_t WatchSession::run(const std::function<void(const WatchEvent&)>& onEvent, Observer* observer,
                              bool once) {
  std::size_t processed = 0;
  int quiet = 0;
  auto stop = [&]() {
    if (!observer) return false;
    IterationSummary s;
    s.iteration = static_cast<long>(processed);
    s.evaluations = polls_;
    return observer->onIteration(s) == ObserverDecision::Stop;
  };
  std::size_t sinceDiagnosis = 0;
  while (!stop()) {
    const std::vector<std::string> names = poll();
    for (std::size_t i = 0; i < names.size(); ++i) {
      ++sinceDiagnosis;
      // Every N-th file (the diagnosis is the slow step: about 0.1-1 s at 100 parts).
      const bool diag = sinceDiagnosis >= static_cast<std::size_t>(options_.diagnoseEvery);
      WatchEvent e = process(names[i], diag);
      if (diag) sinceDiagnosis = 0;
      if (e.file.empty()) continue;  // same content journaled already
      ++processed;
      if (onEvent) onEvent(e);
      if (stop()) return processed;
    }
    // --once: done at the first poll that finds nothing new and nothing still settling.
    if (once) {
      if (names.empty() && seen_.empty()) {
        if (++quiet >= 1) break;
      } else {
        quiet = 0;
      }
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(options_.pollMs);
    while (std::chrono::steady_clock::now() < until) {
      if (stop()) return processed;
      std::this_thread::sleep_for(std::chrono::milliseconds(std::min(20, options_.pollMs)));
    }
  }
  return processed;
}

}  // namespace metrofit
