#include "core/project/project.h"

#include <set>

#include "core/common/error.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"

namespace metrofit {

const DatasetRef* Project::dataset(const std::string& id) const {
  for (const auto& d : datasets) {
    if (d.id == id) return &d;
  }
  return nullptr;
}

const DatasetRef* Project::firstOfKind(const std::string& kind) const {
  for (const auto& d : datasets) {
    if (d.kind == kind) return &d;
  }
  return nullptr;
}

nlohmann::json Project::toJson() const {
  nlohmann::json j;
  j["format"] = kFormatName;
  j["version"] = kFormatVersion;
  j["name"] = name;
  j["description"] = description;
  j["datasets"] = nlohmann::json::array();
  for (const auto& d : datasets) {
    nlohmann::json o{{"id", d.id}, {"kind", d.kind}, {"path", d.path}};
    if (!d.description.empty()) o["description"] = d.description;
    if (!d.licence.empty()) o["licence"] = d.licence;
    j["datasets"].push_back(std::move(o));
  }
  j["studies"] = studies;
  j["results"] = results;
  return j;
}

Project Project::fromJson(const nlohmann::json& j, const std::string& source) {
  JsonReader r(j, source);
  r.requireObject();
  const std::string format = r.string("format");
  if (format != kFormatName)
    r.fail("is '" + format + "', expected '" + kFormatName + "' (not a Metrofit project)", "format");
  const long version = r.integer("version");
  if (version < 1) r.fail("must be 1 or more", "version");
  if (version > kFormatVersion) {
    r.fail("format version " + std::to_string(version) +
               " was written by a newer Metrofit; this build reads up to " + std::to_string(kFormatVersion),
           "version");
  }
  Project p;
  p.name = r.string("name", "Untitled");
  p.description = r.string("description", "");
  if (r.has("datasets")) {
    const JsonReader ds = r.array("datasets");
    std::set<std::string> ids;
    for (std::size_t i = 0; i < ds.size(); ++i) {
      const JsonReader d = ds.at(i);
      d.requireObject();
      DatasetRef ref;
      ref.id = d.string("id");
      if (ref.id.empty()) d.fail("must not be empty", "id");
      if (!ids.insert(ref.id).second) d.fail("duplicate dataset id '" + ref.id + "'", "id");
      ref.kind = d.string("kind");
      ref.path = d.string("path");
      if (ref.path.empty()) d.fail("must not be empty", "path");
      ref.description = d.string("description", "");
      ref.licence = d.string("licence", "");
      p.datasets.push_back(std::move(ref));
    }
  }
  if (r.has("studies")) p.studies = r.object("studies").json();
  if (r.has("results")) p.results = r.object("results").json();
  return p;
}

Project loadProject(const std::string& path) {
  return Project::fromJson(readJsonFile(path), path);
}

void saveProject(const Project& project, const std::string& path) {
  writeFileAtomic(path, dumpJson(project.toJson()));
}

std::string resolveDatasetPath(const std::string& projectPath, const DatasetRef& dataset) {
  return joinPath(parentFolder(projectPath), dataset.path);
}

}  // namespace metrofit
