#include "core/setup/model.h"
#include "core/common/numformat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "core/common/error.h"
#include "core/io/json_util.h"

namespace metrofit::setup {
namespace {

std::string fmt(double v) {
  return num::general(v, 12);
}  // as an ostream's precision(12), C locale

std::string at(const char* list, std::size_t i) {
  return std::string(list) + "[" + std::to_string(i) + "]";
}

/// What a node id refers to.
enum class NodeType { Machine, Wks, Tool, Feature, Dimension };

const char* nodeTypeName(NodeType t) {
  switch (t) {
    case NodeType::Machine:
      return "machine";
    case NodeType::Wks:
      return "wks";
    case NodeType::Tool:
      return "tool";
    case NodeType::Feature:
      return "feature";
    case NodeType::Dimension:
      return "dimension";
  }
  return "?";
}

NodeType typeOf(DatumKind k) {
  switch (k) {
    case DatumKind::Machine:
      return NodeType::Machine;
    case DatumKind::Wks:
      return NodeType::Wks;
    case DatumKind::Tool:
      return NodeType::Tool;
  }
  return NodeType::Wks;
}

bool allowedArc(NodeType from, NodeType to) {
  if (from == NodeType::Machine && to == NodeType::Wks) return true;
  if ((from == NodeType::Machine || from == NodeType::Wks || from == NodeType::Tool) &&
      to == NodeType::Feature)
    return true;
  return from == NodeType::Feature && to == NodeType::Dimension;
}

/// Pair of bounds from a JSON array [lower, upper].
std::pair<double, double> readPair(const JsonReader& parent, const std::string& key) {
  const JsonReader a = parent.array(key);
  if (a.size() != 2) a.fail("expected [lower, upper], found " + std::to_string(a.size()) + " values");
  double v[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& e = a.json()[i];
    if (!e.is_number()) a.at(i).fail(std::string("expected a number, found ") + e.type_name());
    v[i] = e.get<double>();
  }
  return {v[0], v[1]};
}

}  // namespace

const char* toString(DatumKind kind) {
  switch (kind) {
    case DatumKind::Machine:
      return "machine";
    case DatumKind::Wks:
      return "wks";
    case DatumKind::Tool:
      return "tool";
  }
  return "?";
}

int Model::setupIndex(const std::string& id) const {
  for (std::size_t i = 0; i < setup.size(); ++i)
    if (setup[i].id == id) return static_cast<int>(i);
  return -1;
}

int Model::dimensionIndex(const std::string& id) const {
  for (std::size_t i = 0; i < dimensions.size(); ++i)
    if (dimensions[i].id == id) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> Model::setupIds() const {
  std::vector<std::string> out;
  for (const auto& s : setup) out.push_back(s.id);
  return out;
}

std::vector<std::string> Model::dimensionIds() const {
  std::vector<std::string> out;
  for (const auto& d : dimensions) out.push_back(d.id);
  return out;
}

std::vector<ModelIssue> checkModel(const Model& m) {
  std::vector<ModelIssue> issues;
  auto add = [&](std::string field, std::string message, std::vector<std::string> nodes = {}) {
    issues.push_back({std::move(field), std::move(message), std::move(nodes)});
  };

  // ---- scalars ----
  if (m.axis != "X" && m.axis != "Y" && m.axis != "Z")
    add("axis", "unknown axis '" + m.axis + "' (expected X, Y or Z)");
  if (!std::isfinite(m.stepMm) || m.stepMm <= 0.0)
    add("step_mm", "the grid step must be positive (got " + fmt(m.stepMm) + ")");
  auto checkBounds = [&](const std::pair<double, double>& b, const std::string& field,
                         const std::string& node) {
    const std::vector<std::string> nodes = node.empty() ? std::vector<std::string>{} : std::vector{node};
    if (!std::isfinite(b.first) || !std::isfinite(b.second)) {
      add(field, "bounds must be finite numbers", nodes);
    } else if (b.first > b.second) {
      add(field, "lower bound " + fmt(b.first) + " is above upper bound " + fmt(b.second), nodes);
    } else if (std::isfinite(m.stepMm) && m.stepMm > 0.0 && (b.second - b.first) / m.stepMm > 1e9) {
      add(field, "more than 1e9 grid steps between the bounds", nodes);
    }
  };
  checkBounds(m.boundsMm, "bounds_mm", {});

  // ---- sets and ids (one namespace; global index: setup, then features, then dimensions) ----
  if (m.setup.empty())
    add("setup", "is empty: the model needs at least one setup datum (wks, tool or machine)");
  if (m.features.empty()) add("features", "is empty: the model needs at least one feature");
  if (m.dimensions.empty()) add("dimensions", "is empty: the model needs at least one dimension");
  if (m.arcs.empty()) add("arcs", "is empty: the model needs arcs from setup data to features to dimensions");

  const std::size_t nS = m.setup.size(), nF = m.features.size(), nD = m.dimensions.size();
  std::vector<NodeType> types(nS + nF + nD, NodeType::Feature);
  std::vector<std::string> defined(nS + nF + nD);  // field that defines node g
  std::unordered_map<std::string, std::size_t> nodes;
  nodes.reserve(nS + nF + nD);
  auto define = [&](const std::string& id, NodeType type, std::size_t g, const std::string& field) {
    types[g] = type;
    defined[g] = field;
    if (id.empty()) {
      add(field + ".id", "empty id");
      return;
    }
    const auto [it, inserted] = nodes.emplace(id, g);
    if (!inserted)
      add(field + ".id", "duplicate id '" + id + "' (already used by " + defined[it->second] + ")", {id});
  };
  for (std::size_t i = 0; i < nS; ++i) {
    define(m.setup[i].id, typeOf(m.setup[i].kind), i, at("setup", i));
    if (m.setup[i].boundsMm) checkBounds(*m.setup[i].boundsMm, at("setup", i) + ".bounds_mm", m.setup[i].id);
    if (m.setup[i].registerNumber < 0)
      add(at("setup", i) + ".register", "register number must not be negative", {m.setup[i].id});
  }
  for (std::size_t i = 0; i < nF; ++i) define(m.features[i].id, NodeType::Feature, nS + i, at("features", i));
  for (std::size_t i = 0; i < nD; ++i) {
    const Dimension& d = m.dimensions[i];
    define(d.id, NodeType::Dimension, nS + nF + i, at("dimensions", i));
    if (!std::isfinite(d.lower) || !std::isfinite(d.upper)) {
      add(at("dimensions", i), "tolerance limits must be finite numbers", {d.id});
    } else if (d.lower >= d.upper) {
      add(at("dimensions", i),
          "lower limit " + fmt(d.lower) + " is not below upper limit " + fmt(d.upper) + " (dimension '" +
              d.id + "')",
          {d.id});
    }
    if (d.nominal && !std::isfinite(*d.nominal))
      add(at("dimensions", i) + ".nominal", "not a finite number", {d.id});
  }

  // ---- arcs: end points, weights, duplicates ----
  const std::size_t nA = m.arcs.size();
  std::vector<bool> arcUsable(nA, false);
  std::vector<std::size_t> from(nA, 0), to(nA, 0);
  std::unordered_map<std::uint64_t, std::size_t> seen;
  seen.reserve(nA);
  for (std::size_t a = 0; a < nA; ++a) {
    const Arc& arc = m.arcs[a];
    const std::string f = at("arcs", a);
    bool ok = true;
    for (const bool isFrom : {true, false}) {
      const std::string& end = isFrom ? arc.from : arc.to;
      const auto it = nodes.find(end);
      if (it == nodes.end()) {
        add(f + (isFrom ? ".from" : ".to"),
            "unknown node '" + end + "' (not a setup datum, feature or dimension of the model)", {end});
        ok = false;
      } else {
        (isFrom ? from : to)[a] = it->second;
      }
    }
    if (!(arc.weight == 1.0 || arc.weight == -1.0)) {
      add(f + ".weight", "weight " + fmt(arc.weight) + " is not +1 or -1", {arc.from, arc.to});
      ok = false;
    }
    if (!ok) continue;
    const std::uint64_t key = (static_cast<std::uint64_t>(from[a]) << 32) | static_cast<std::uint64_t>(to[a]);
    const auto [it, inserted] = seen.emplace(key, a);
    if (!inserted) {
      add(f, "duplicate arc " + arc.from + " -> " + arc.to + " (first at " + at("arcs", it->second) + ")",
          {arc.from, arc.to});
      continue;
    }
    arcUsable[a] = true;
  }

  // ---- cycles: iterative depth-first search over the usable arcs, in file order ----
  std::vector<std::vector<std::size_t>> out(types.size());
  for (std::size_t a = 0; a < nA; ++a)
    if (arcUsable[a]) out[from[a]].push_back(a);
  std::vector<bool> closesCycle(nA, false);
  {
    std::vector<char> state(types.size(), 0);             // 0 new, 1 on the stack, 2 done
    std::vector<std::pair<std::size_t, std::size_t>> st;  // (node, next out-arc position)
    for (std::size_t a0 = 0; a0 < nA; ++a0) {
      if (!arcUsable[a0] || state[from[a0]] != 0) continue;
      st.push_back({from[a0], 0});
      state[from[a0]] = 1;
      while (!st.empty()) {
        auto& [node, pos] = st.back();
        if (pos == out[node].size()) {
          state[node] = 2;
          st.pop_back();
          continue;
        }
        const std::size_t a = out[node][pos++];
        const std::size_t next = to[a];
        if (state[next] == 1) {
          std::size_t k = 0;
          while (st[k].first != next) ++k;
          std::string path;
          std::vector<std::string> involved;
          for (std::size_t h = k; h < st.size(); ++h) {
            const std::size_t g = st[h].first;
            const std::string& id = g < nS        ? m.setup[g].id
                                    : g < nS + nF ? m.features[g - nS].id
                                                  : m.dimensions[g - nS - nF].id;
            path += id + " -> ";
            involved.push_back(id);
          }
          path += m.arcs[a].to;
          closesCycle[a] = true;
          add(at("arcs", a), "arc " + m.arcs[a].from + " -> " + m.arcs[a].to + " closes a cycle " + path,
              involved);
        } else if (state[next] == 0) {
          state[next] = 1;
          st.push_back({next, 0});
        }
      }
    }
  }

  // ---- directions ----
  bool graphValid = true;
  for (std::size_t a = 0; a < nA; ++a) {
    if (!arcUsable[a] || closesCycle[a]) {
      graphValid = false;
      continue;
    }
    const Arc& arc = m.arcs[a];
    if (!allowedArc(types[from[a]], types[to[a]])) {
      graphValid = false;
      add(at("arcs", a),
          "arc " + arc.from + " -> " + arc.to + " goes from " + nodeTypeName(types[from[a]]) + " to " +
              nodeTypeName(types[to[a]]) +
              "; allowed: machine -> wks, machine/wks/tool -> feature, feature -> dimension",
          {arc.from, arc.to});
    }
  }

  // ---- every dimension needs a path to setup data ----
  if (graphValid && issues.empty()) {
    std::vector<char> reached(types.size(), 0), hasInput(types.size(), 0), hasPath(types.size(), 0);
    for (std::size_t a = 0; a < nA; ++a)
      if (types[to[a]] == NodeType::Feature) reached[to[a]] = 1;
    for (std::size_t a = 0; a < nA; ++a) {
      if (types[to[a]] != NodeType::Dimension) continue;
      hasInput[to[a]] = 1;
      if (reached[from[a]]) hasPath[to[a]] = 1;
    }
    for (std::size_t i = 0; i < nD; ++i) {
      const std::size_t g = nS + nF + i;
      const std::string& id = m.dimensions[i].id;
      if (!hasInput[g]) {
        add(at("dimensions", i), "dimension '" + id + "' has no path to setup data (no arc from a feature)",
            {id});
      } else if (!hasPath[g]) {
        add(at("dimensions", i),
            "dimension '" + id + "' has no path to setup data (its features have no arc from a setup datum)",
            {id});
      }
    }
  }
  return issues;
}

void validateModel(const Model& model) {
  const auto issues = checkModel(model);
  if (issues.empty()) return;
  throw ValidationError(ErrorContext{model.source, 0, 0, issues.front().field}, issues.front().message);
}

Model modelFromJson(const nlohmann::json& json, const std::string& source) {
  const JsonReader r(json, source);
  r.requireObject();
  Model m;
  m.source = source;
  m.name = r.string("name", "");
  m.axis = r.string("axis", "Z");
  m.stepMm = r.number("step_mm", 0.001);
  if (r.has("bounds_mm")) m.boundsMm = readPair(r, "bounds_mm");

  const JsonReader setup = r.array("setup");
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const JsonReader e = setup.at(i);
    SetupDatum d;
    d.id = e.string("id");
    const std::string kind = e.string("kind");
    if (kind == "machine")
      d.kind = DatumKind::Machine;
    else if (kind == "wks")
      d.kind = DatumKind::Wks;
    else if (kind == "tool")
      d.kind = DatumKind::Tool;
    else
      e.fail("unknown kind '" + kind + "' (expected machine, wks or tool)", "kind");
    if (e.has("bounds_mm")) d.boundsMm = readPair(e, "bounds_mm");
    if (e.has("register")) {
      const long reg = e.integer("register");
      if (reg < 0 || reg > 99999) e.fail("register number must be in 0..99999", "register");
      d.registerNumber = static_cast<int>(reg);
    }
    m.setup.push_back(std::move(d));
  }
  const JsonReader features = r.array("features");
  for (std::size_t i = 0; i < features.size(); ++i) m.features.push_back({features.at(i).string("id")});
  const JsonReader dims = r.array("dimensions");
  for (std::size_t i = 0; i < dims.size(); ++i) {
    const JsonReader e = dims.at(i);
    Dimension d;
    d.id = e.string("id");
    if (e.has("nominal")) d.nominal = e.number("nominal");
    d.lower = e.number("lower");
    d.upper = e.number("upper");
    d.label = e.string("label", "");
    m.dimensions.push_back(std::move(d));
  }
  const JsonReader arcs = r.array("arcs");
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const JsonReader e = arcs.at(i);
    Arc a;
    a.from = e.string("from");
    a.to = e.string("to");
    a.weight = e.number("weight");
    m.arcs.push_back(std::move(a));
  }
  validateModel(m);
  return m;
}

Model readModel(const std::string& path) {
  return modelFromJson(readJsonFile(path), path);
}

nlohmann::json modelToJson(const Model& m) {
  nlohmann::json j;
  j["name"] = m.name;
  j["axis"] = m.axis;
  j["step_mm"] = m.stepMm;
  j["bounds_mm"] = {m.boundsMm.first, m.boundsMm.second};
  j["setup"] = nlohmann::json::array();
  for (const auto& s : m.setup) {
    nlohmann::json e{{"id", s.id}, {"kind", toString(s.kind)}};
    if (s.boundsMm) e["bounds_mm"] = {s.boundsMm->first, s.boundsMm->second};
    if (s.registerNumber > 0) e["register"] = s.registerNumber;
    j["setup"].push_back(e);
  }
  j["features"] = nlohmann::json::array();
  for (const auto& f : m.features) j["features"].push_back({{"id", f.id}});
  j["dimensions"] = nlohmann::json::array();
  for (const auto& d : m.dimensions) {
    nlohmann::json e{{"id", d.id}, {"lower", d.lower}, {"upper", d.upper}};
    if (d.nominal) e["nominal"] = *d.nominal;
    if (!d.label.empty()) e["label"] = d.label;
    j["dimensions"].push_back(e);
  }
  j["arcs"] = nlohmann::json::array();
  for (const auto& a : m.arcs) {
    const int w = a.weight < 0 ? -1 : 1;
    j["arcs"].push_back({{"from", a.from},
                         {"to", a.to},
                         {"weight", a.weight == w ? nlohmann::json(w) : nlohmann::json(a.weight)}});
  }
  return j;
}

Eigen::MatrixXd gainMatrix(const Model& m) {
  validateModel(m);
  const std::size_t nS = m.setup.size(), nF = m.features.size(), nD = m.dimensions.size();
  std::unordered_map<std::string, std::size_t> index;
  index.reserve(nS + nF + nD);
  for (std::size_t i = 0; i < nS; ++i) index.emplace(m.setup[i].id, i);
  for (std::size_t i = 0; i < nF; ++i) index.emplace(m.features[i].id, nS + i);
  for (std::size_t i = 0; i < nD; ++i) index.emplace(m.dimensions[i].id, nS + nF + i);
  // Incoming arcs per node; influence of every node as a sparse row over the setup data.
  std::vector<std::vector<std::pair<std::size_t, double>>> in(nS + nF + nD), total(nS + nF + nD);
  for (const Arc& a : m.arcs) in[index.at(a.to)].emplace_back(index.at(a.from), a.weight);
  std::vector<double> acc(nS, 0.0);
  std::vector<char> mark(nS, 0);
  std::vector<std::size_t> touched;
  auto combine = [&](std::size_t node, bool unit) {
    touched.clear();
    auto bump = [&](std::size_t i, double v) {
      if (!mark[i]) {
        mark[i] = 1;
        touched.push_back(i);
      }
      acc[i] += v;
    };
    if (unit) bump(node, 1.0);
    for (const auto& [src, w] : in[node])
      for (const auto& [i, v] : total[src]) bump(i, w * v);
    std::sort(touched.begin(), touched.end());
    for (const std::size_t i : touched) {
      if (acc[i] != 0.0) total[node].emplace_back(i, acc[i]);
      acc[i] = 0.0;
      mark[i] = 0;
    }
  };
  // Level order (validated): machine points, then WKS / tools (with machine -> wks), features, dimensions.
  for (std::size_t i = 0; i < nS; ++i)
    if (m.setup[i].kind == DatumKind::Machine) combine(i, true);
  for (std::size_t i = 0; i < nS; ++i)
    if (m.setup[i].kind != DatumKind::Machine) combine(i, true);
  for (std::size_t g = nS; g < nS + nF + nD; ++g) combine(g, false);
  Eigen::MatrixXd gain = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(nD), static_cast<Eigen::Index>(nS));
  for (std::size_t q = 0; q < nD; ++q)
    for (const auto& [i, v] : total[nS + nF + q])
      gain(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(i)) = v;
  return gain;
}

}  // namespace metrofit::setup
