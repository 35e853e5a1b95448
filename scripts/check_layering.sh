#!/usr/bin/env bash
# Checks the include structure of the sources: no file includes another module's detail/
# header (those are internal and not installed), and no module of src/roomscout includes a
# module of a higher layer. Prints every violation and exits 1 if there is any.
#
# The layers, lowest first, follow the libraries of src/CMakeLists.txt (docs/development.md,
# "Source tree"): the core library (core; then mapping, planning and maps; exploration; the
# explorer), then io and slam, sim and plots, experiment, and the command line. Modules of one
# layer do not include each other. Tests may include the detail/ headers of the module they
# mirror (tests/<module>/).
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A layer=(
  [core]=0
  [mapping]=1 [planning]=1 [maps]=1
  [exploration]=2
  [explorer]=3
  [io]=4 [slam]=4
  [sim]=5 [plots]=5
  [experiment]=6
  [cli]=7
)

failures=0
fail() {
  echo "$1"
  failures=$((failures + 1))
}

for module in src/roomscout/*/; do
  module=$(basename "$module")
  [[ -n "${layer[$module]+set}" ]] || fail "src/roomscout/$module: not in a layer: add it to scripts/check_layering.sh"
done

while IFS= read -r file; do
  # The module a file belongs to: src/roomscout/<m>/... or tests/<m>/...
  own=""
  if [[ "$file" =~ ^src/roomscout/([a-z_]+)/ ]]; then
    own="${BASH_REMATCH[1]}"
  elif [[ "$file" =~ ^tests/([a-z_]+)/ ]]; then
    own="${BASH_REMATCH[1]}"
  fi
  while IFS= read -r line; do
    [[ "$line" =~ ^([0-9]+):[[:space:]]*#[[:space:]]*include[[:space:]]+\"roomscout/([a-z_]+)/(.*)\" ]] || continue
    number="${BASH_REMATCH[1]}"
    included="${BASH_REMATCH[2]}"
    rest="${BASH_REMATCH[3]}"
    if [[ "$rest" == detail/* && "$included" != "$own" ]]; then
      fail "$file:$number: includes roomscout/$included/$rest, an internal header of another module"
    fi
    if [[ "$file" == src/roomscout/* && "$included" != "$own" && -n "${layer[$included]+set}" ]]; then
      if ((layer[$included] >= layer[$own])); then
        fail "$file:$number: $own (layer ${layer[$own]}) includes roomscout/$included/$rest (layer ${layer[$included]})"
      fi
    fi
  done < <(grep -n '#[[:space:]]*include' "$file" || true)
done < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')

if ((failures > 0)); then
  echo "check_layering: $failures violation(s)"
  exit 1
fi
echo "check_layering: ok"
