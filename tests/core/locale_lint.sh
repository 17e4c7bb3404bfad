#!/usr/bin/env bash
# Numbers in files never follow the process locale (issue 27; core/common/numformat.h):
#   tests/core/locale_lint.sh <source root>
# Refuses, in core/, widgets/ and app/ (sources and headers), the conversions whose output or input
# depends on setlocale: std::snprintf / sprintf / vsnprintf (strings that go into files and texts),
# strtod / strtof / strtold, std::stod / stof / stold and atof. Integer conversions (%d, std::stoi)
# are locale free and allowed; so is fprintf/printf to the terminal (the CLI's messages: the
# programs set LC_NUMERIC to "C" after creating the Qt application).
# Allowed everywhere: core/common/numformat.cpp, the one place that calls them under an explicit C
# locale. std::to_string of a floating value is locale dependent too; a regular expression cannot
# see the argument's type, so tests/core/locale_to_string_check.cmake checks it at compile time.
# Every violation is printed as "<file>:<line>: <code>"; exit 1 if any.
set -euo pipefail
root="${1:?usage: locale_lint.sh <source root>}"
cd "$root"
pattern='(^|[^A-Za-z_:.>])(std::)?(v?sn?printf|strto(d|f|ld)|sto(d|f|ld)|atof)[[:space:]]*\('
found=0
while IFS= read -r f; do
  [ "$f" = "core/common/numformat.cpp" ] && continue
  # comments and string literals out (line numbers kept), then the pattern
  hits=$(sed -E 's://.*$::; s/"([^"\\]|\\.)*"/""/g' "$f" | grep -nE "$pattern" || true)
  if [ -n "$hits" ]; then
    while IFS= read -r h; do
      n=${h%%:*}
      echo "$f:$n: $(sed -n "${n}p" "$f" | sed -E 's/^[[:space:]]+//')"
      found=$((found + 1))
    done <<<"$hits"
  fi
done < <(find core widgets app -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
if [ "$found" -gt 0 ]; then
  echo "locale lint: $found locale-dependent number conversion(s); use metrofit::c_snprintf, cformat," \
       "num::fixed / general / parseDouble / strtodC (core/common/numformat.h)" >&2
  exit 1
fi
echo "locale lint: ok"
