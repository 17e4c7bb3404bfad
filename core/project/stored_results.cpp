#include "core/project/stored_results.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <ctime>

#include "core/common/error.h"
#include "core/io/file_io.h"

namespace metrofit {
namespace {

void mix(std::uint64_t& h, const std::string& bytes) {
  for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
}

/// How the project reads the dataset (its JSON entry without id, path, description and licence).
std::string readingOptions(const DatasetRef& dataset) {
  Project p;
  p.datasets.push_back(dataset);
  nlohmann::json j = p.toJson()["datasets"][0];
  for (const char* key : {"id", "path", "paths", "description", "licence"}) j.erase(key);
  return j.dump();
}

}  // namespace

std::string datasetDataHash(const std::string& projectPath, const DatasetRef& dataset) {
  std::uint64_t h = 1469598103934665603ull;
  // A DMIS series: every file, in order (a single file hashes as before).
  for (const std::string& file : resolveDatasetPaths(projectPath, dataset)) mix(h, readFile(file));
  mix(h, readingOptions(dataset));
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "fnv1a64:";
  for (int shift = 60; shift >= 0; shift -= 4) out += kHex[(h >> shift) & 0xF];
  return out;
}

std::string utcTimestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  std::array<char, 32> buffer{};
  std::strftime(buffer.data(), buffer.size(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer.data();
}

StoredResult storedResult(const Project& project, const std::string& projectPath, const std::string& study,
                          const DatasetRef& dataset, const nlohmann::json& settings) {
  StoredResult out;
  const auto s = project.results.find(study);
  if (s == project.results.end() || !s->is_object()) return out;
  const auto e = s->find(dataset.id);
  if (e == s->end() || !e->is_object()) return out;
  out.entry = *e;
  out.computed = e->value("computed", std::string());
  if (e->value("settings", nlohmann::json()) != settings) {
    out.state = StoredResultState::SettingsChanged;
    return out;
  }
  std::string hash;
  try {
    hash = datasetDataHash(projectPath, dataset);
  } catch (const std::exception&) {
    out.state = StoredResultState::DataMissing;
    return out;
  }
  out.state = e->value("data_hash", std::string()) == hash ? StoredResultState::Current
                                                           : StoredResultState::DataChanged;
  return out;
}

nlohmann::json makeStoredResult(const std::string& projectPath, const DatasetRef& dataset,
                                const nlohmann::json& settings, nlohmann::json figures) {
  if (!figures.is_object()) figures = nlohmann::json::object();
  figures["settings"] = settings;
  figures["data_hash"] = datasetDataHash(projectPath, dataset);
  figures["computed"] = utcTimestamp();
  return figures;
}

void setStoredResult(Project& project, const std::string& study, const std::string& datasetId,
                     nlohmann::json entry) {
  if (!project.results.is_object()) project.results = nlohmann::json::object();
  nlohmann::json& s = project.results[study];
  if (!s.is_object()) s = nlohmann::json::object();
  s[datasetId] = std::move(entry);
}

}  // namespace metrofit
