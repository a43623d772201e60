#!/usr/bin/env bash
# The CI's style guards: every source formatted as .clang-format says
# (clang-format), and the sources a change touches free of .clang-tidy's
# findings (clang-tidy, warnings are errors). The change: the commits since
# RBS_LINT_BASE (default HEAD~1, the last commit; e.g. RBS_LINT_BASE=origin/main
# before pushing). Builds the package first (with warnings as errors), for
# its compile_commands.json and generated headers.
set -euo pipefail
source "$(dirname "$0")/common.sh"
cd "$RBS_ROOT"
rbs_install_packages "${RBS_APT_PACKAGES[@]}" clang-format clang-tidy
rbs_build

mapfile -t sources < <(git ls-files '*.h' '*.cpp')
echo "lint: clang-format over ${#sources[@]} sources" >&2
clang-format --dry-run --Werror "${sources[@]}"

# The docs a newcomer reads stay short and ARCHITECTURE.md names every
# source unit (a header or source of the same stem names both).
docs_ok=1
for limit in README.md:300 bench/README.md:400; do
  lines=$(wc -l <"${limit%%:*}")
  if [ "$lines" -gt "${limit##*:}" ]; then
    echo "lint: ${limit%%:*} has $lines lines, at most ${limit##*:}: move reference text to docs/" >&2
    docs_ok=0
  fi
done
for f in $(git ls-files src include); do
  stem=$(basename "${f%.*}")
  if ! grep -qE "\b$stem\.(h|cpp)\b" ARCHITECTURE.md; then
    echo "lint: ARCHITECTURE.md does not name $f" >&2
    docs_ok=0
  fi
done
[ "$docs_ok" -eq 1 ] || exit 1
echo "lint: docs: README.md, bench/README.md within their lengths; ARCHITECTURE.md names every source unit" >&2

# What the code says to users (logs, service answers, stderr) is plain
# ASCII: ROS 1's logs print other bytes as '???'. Comments may use any.
mapfile -t code < <(git ls-files 'src/*.h' 'src/*.cpp' 'include/*.h')
if grep -nP '^(?!\s*(//|\*|/\*)).*"[^"]*[^\x00-\x7F][^"]*"' "${code[@]}"; then
  echo "lint: a string literal above is not plain ASCII: ROS logs would print it as ???" >&2
  exit 1
fi
echo "lint: strings: plain ASCII in ${#code[@]} sources" >&2

# The translation units of the change under src/: changed .cpp files, and
# the .cpp beside a changed header (its checks run through HeaderFilterRegex).
base=${RBS_LINT_BASE:-HEAD~1}
if git rev-parse -q --verify "$base^{commit}" >/dev/null; then
  mapfile -t changed < <(git diff --name-only --diff-filter=d "$base" -- src include)
else
  mapfile -t changed < <(git ls-files src include)
fi
units=()
for f in "${changed[@]}"; do
  stem=$(basename "${f%.*}")
  case "$f" in
    *.cpp) units+=("$f") ;;
    *.h) while IFS= read -r u; do units+=("$u"); done < <(git ls-files "src/*/$stem.cpp" "src/$stem.cpp") ;;
  esac
done
mapfile -t units < <(printf '%s\n' "${units[@]}" | sort -u | sed '/^$/d')
if [ ${#units[@]} -eq 0 ]; then
  echo "lint: no sources under src/ changed since $base: clang-tidy has nothing to check" >&2
  exit 0
fi
echo "lint: clang-tidy over ${#units[@]} sources changed since $base (about 10 s each, 2 at a time)" >&2
# The build's paths are the workspace's links to these files. The core's
# flags carry GCC's -fno-fat-lto-objects (link-time optimisation), which
# clang does not know: not a finding.
# The build's precompiled headers are GCC's, which clang cannot read: it
# reads each source as written, without them (its own includes only).
tidy=$RBS_WS/tidy
mkdir -p "$tidy"
sed -E 's# -Winvalid-pch -include [^ ]*/cmake_pch\.hxx##g' "$RBS_WS/build/compile_commands.json" >"$tidy/compile_commands.json"
status=0
printf "$RBS_WS/src/rigid_body_sim/%s\n" "${units[@]}" |
  xargs -P 2 -n 1 clang-tidy --quiet -p "$tidy" --extra-arg=-Wno-ignored-optimization-argument 2>/dev/null ||
  status=1
[ "$status" -eq 0 ] && echo "lint: clean" >&2
exit "$status"
