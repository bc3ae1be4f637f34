#!/usr/bin/env bash
# Formatting: every tracked C and C++ file as .clang-format (VTK's style) has it, by Debian 12's
# clang-format 14; fails listing the files that differ (fix them with
# `clang-format -i FILE...`; the first lines of each difference are printed). Python and CMake
# files are not checked.
#
# Needs clang-format (installed here with apt-get when missing: scripts/lib.sh, as root or
# through sudo). Takes a few seconds.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

# Debian 12's clang-format is version 14; another version formats some constructs otherwise.
if ! command -v clang-format-14 > /dev/null && ! command -v clang-format > /dev/null; then
  echo "== format: installing clang-format"
  . "$root/scripts/lib.sh"
  ensure_packages clang-format
fi
format=$(command -v clang-format-14 || command -v clang-format)
version=$("$format" --version | sed -n '1p')
case "$version" in
  *" 14."*) ;;
  *) echo "== format: warning: $version is not version 14" >&2 ;;
esac

mapfile -t files < <(git ls-files '*.h' '*.hpp' '*.c' '*.cxx' '*.cpp' '*.txx')
if [ "${#files[@]}" -eq 0 ]; then
  echo "== format: no C or C++ files found (not a git checkout?)" >&2
  exit 1
fi
unformatted=()
for f in "${files[@]}"; do
  if ! report=$("$format" --style=file --dry-run --Werror "$f" 2>&1); then
    unformatted+=("$f")
    printf '%s\n' "$report" | sed -n '1,6p' >&2 # the first difference, or why it failed
  fi
done
echo "== format: $version; ${#files[@]} files checked"
if [ "${#unformatted[@]}" -ne 0 ]; then
  echo "== format: ${#unformatted[@]} files differ from .clang-format (or could not be read):" >&2
  printf '   %s\n' "${unformatted[@]}" >&2
  exit 1
fi
