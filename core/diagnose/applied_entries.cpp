#include "core/diagnose/applied_entries.h"

#include "core/common/error.h"

namespace metrofit::diagnose {
namespace {

[[noreturn]] void fail(const AppliedEntryMessages& m, const std::string& field, const std::string& what) {
  throw ValidationError(ErrorContext{m.source, 0, 0, field}, what);
}

}  // namespace

AppliedEntryMessages appliedMessagesKnown(const std::string& known) {
  AppliedEntryMessages m;
  m.notList = "must be a list of {\"name\", \"parameters\"}";
  m.notObject = "must be an object {\"name\", \"parameters\"}";
  m.nameMissing = m.nameInvalid = "must be the effect's name (" + known + ")";
  return m;
}

AppliedEntryMessages appliedMessagesOf(const std::string& source) {
  AppliedEntryMessages m;
  m.source = source;
  m.notList = "must be a list of effects";
  m.notObject = "must be an object {\"name\": ..., \"parameters\": {...}}";
  m.nameMissing = "is missing";
  m.nameInvalid = "must be the name of an effect (text)";
  m.rejectEmptyName = true;
  return m;
}

std::string appliedEntryField(const std::string& field, std::size_t i, const std::string& key) {
  std::string f = field + "[" + std::to_string(i) + "]";
  return key.empty() ? f : f + "." + key;
}

bool isAppliedList(const nlohmann::json& applied, const std::string& field,
                   const AppliedEntryMessages& messages) {
  if (applied.is_null()) return false;
  if (!applied.is_array()) fail(messages, field, messages.notList);
  return true;
}

void forEachAppliedEntry(const nlohmann::json& applied, const std::string& field,
                         const AppliedEntryMessages& messages,
                         const std::function<void(const AppliedEntry&)>& fn) {
  if (!isAppliedList(applied, field, messages)) return;
  for (std::size_t i = 0; i < applied.size(); ++i) {
    const nlohmann::json& e = applied[i];
    const std::string at = appliedEntryField(field, i);
    if (!e.is_object()) fail(messages, at, messages.notObject);
    const auto it = e.find("name");
    if (it == e.end()) fail(messages, at + ".name", messages.nameMissing);
    if (!it->is_string() || (messages.rejectEmptyName && it->get<std::string>().empty()))
      fail(messages, at + ".name", messages.nameInvalid);
    fn(AppliedEntry{i, e, it->get<std::string>(), at});
  }
}

}  // namespace metrofit::diagnose
