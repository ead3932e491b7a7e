#!/usr/bin/env bash
# Fails, listing the files, when a C++ source differs from what the repo's .clang-format makes.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t sources < <(git ls-files '*.cpp' '*.h')
if ! clang-format --dry-run --Werror "${sources[@]}" 2> build-format.log; then
  grep -o '^[^:]*:' build-format.log | sort -u | sed 's/:$//; s/^/not formatted: /'
  echo "format: 0 passed, 1 failed (run clang-format -i on the files above)"
  exit 1
fi
rm -f build-format.log
echo "format: ${#sources[@]} files checked"
