#pragma once
// The common preamble of the applied-effects parsers (studies.diagnosis.<domain>.applied, written by
// Apply on the diagnosis page): the list is null (nothing applied) or a list; every entry is an
// object with a "name" text; the rest of an entry ("parameters") is the domain's. Used by the thermal
// (core/diagnose/thermal_applied.h), kinematic (core/diagnose/applied_kinematic.h), setup and matching
// (core/diagnose/applied_setup_matching.h) parsers. The wording of the errors is the domain's (the
// thermal and kinematic parsers name the known effects, the setup and matching ones the project
// file); every error is a ValidationError naming `field`, `field[i]` or `field[i].name`.
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "core/diagnose/residual_check.h"

namespace metrofit::diagnose {

/// How a parser words the preamble's errors.
struct AppliedEntryMessages {
  std::string source;       ///< file named in the errors (may be empty)
  std::string notList;      ///< the list is neither null nor a list
  std::string notObject;    ///< an entry is not an object
  std::string nameMissing;  ///< an entry has no "name"
  std::string nameInvalid;  ///< "name" is not text (or empty text, when rejectEmptyName)
  bool rejectEmptyName = false;
};

/// The thermal and kinematic wording: no file, `known` lists the effects, e.g.
/// "lag, lag:<column>, input:<column>, drift"; an empty name passes (the parser rejects it as unknown).
AppliedEntryMessages appliedMessagesKnown(const std::string& known);
/// The setup and matching wording: errors name `source`; an empty name is rejected.
AppliedEntryMessages appliedMessagesOf(const std::string& source);

/// "field[i]" or "field[i].key".
std::string appliedEntryField(const std::string& field, std::size_t i, const std::string& key = {});

/// One checked entry of an applied list.
struct AppliedEntry {
  std::size_t index = 0;
  const nlohmann::json& json;  ///< the entry (an object)
  std::string name;            ///< its "name"
  std::string field;           ///< "field[i]"

  /// "field[i].key" ("field[i]" for an empty key).
  std::string at(const std::string& key) const { return key.empty() ? field : field + "." + key; }
};

/// True for a list, false for null (nothing applied); throws ValidationError(messages.notList)
/// naming `field` for anything else.
bool isAppliedList(const nlohmann::json& applied, const std::string& field,
                   const AppliedEntryMessages& messages);

/// Checks the list (isAppliedList) and calls `fn` for every entry in order, after checking that the
/// entry is an object with a "name" text (errors naming field[i] and field[i].name). Nothing for null.
void forEachAppliedEntry(const nlohmann::json& applied, const std::string& field,
                         const AppliedEntryMessages& messages,
                         const std::function<void(const AppliedEntry&)>& fn);

/// A generic effect (`unexplained:<against>`, docs/file-formats.md#generic-effects) as Apply stores it: its
/// fixed shape under the entry's "shape" key, so that a study evaluates the same basis the diagnosis
/// fitted: {"against", "form" (linear|smooth|step|periodic|level), "knots", "harmonics", "levels",
/// "centre", "scale", "subset", "without_linear", "components"}.
nlohmann::json genericShapeJson(const GenericForm& form);
/// The shape of an `unexplained:<against>` entry; ValidationError naming "<field[i]>.shape" or
/// "<field[i]>.shape.<key>" for a missing shape, a wrong type, an unknown form, knots that are not
/// finite and increasing (smooth: at least two), harmonics or levels out of range, a scale that is
/// not positive, or an `against` that is not the name's.
GenericForm genericShapeOf(const AppliedEntry& entry, const std::string& source = {});

}  // namespace metrofit::diagnose
