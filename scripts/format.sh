#!/usr/bin/env bash
# Formats the C++ sources with clang-format and the repository's .clang-format.
# Usage: scripts/format.sh            rewrite every tracked .cpp/.hpp in place
#        scripts/format.sh --check    change nothing; list the files that would
#                                     change and exit 1 if there are any
#        scripts/format.sh [--check] FILE...   only these files
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [ "${1:-}" = "--check" ]; then
  check=1
  shift
fi
clang_format=${CLANG_FORMAT:-clang-format}
if ! command -v "$clang_format" >/dev/null; then
  echo "format.sh: $clang_format not found (Debian: apt-get install clang-format)" >&2
  exit 2
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp')
  else  # a source tree without git: the project's own folders
    mapfile -t files < <(find engine testbed tests \( -name '*.cpp' -o -name '*.hpp' \) | sort)
  fi
fi
if [ ${#files[@]} -eq 0 ]; then
  exit 0
fi
if [ $check = 0 ]; then
  "$clang_format" -i --style=file "${files[@]}"
  exit 0
fi
# One clang-format process for every file; each file that would change is
# named in its diagnostics ("FILE:LINE:COL: error: code should be
# clang-formatted").
if report=$("$clang_format" --style=file --dry-run --Werror "${files[@]}" 2>&1 >/dev/null); then
  exit 0
fi
printf '%s\n' "$report" | sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u
if ! printf '%s\n' "$report" | grep -q 'code should be clang-formatted'; then
  printf '%s\n' "$report" >&2  # a failure other than formatting (an unreadable file)
fi
echo "format.sh: the files above are not formatted (run scripts/format.sh)" >&2
exit 1
