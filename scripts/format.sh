#!/usr/bin/env bash
# The C++ sources in the style of .clang-format (Debian 12's clang-format 14).
#   scripts/format.sh          rewrite them
#   scripts/format.sh --check  list the files that differ and fail (make test runs this)
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files 'src/*.h' 'src/*.cpp' 'tests/kernel/*.cpp')
if [ "${1:-}" = --check ]; then
  bad=0
  for f in "${files[@]}"; do
    clang-format --style=file --dry-run --Werror "$f" >/dev/null 2>&1 || { echo "format: $f differs (run make format)"; bad=1; }
  done
  [ $bad = 0 ] && echo "format: ${#files[@]} C++ files follow .clang-format"
  exit $bad
fi
clang-format --style=file -i "${files[@]}"
