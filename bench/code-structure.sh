#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# How big the core's pieces are: the largest files of lib/src and the largest functions
# (lines from a function's first line to its closing brace, universal-ctags' end field).
#   bash bench/code-structure.sh [REV] [N]   (default: the working tree, 10 rows each)
# With REV, that revision's lib/src is read from git (e.g. 9a9077a, before the redesign).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

rev=${1:-}
rows=${2:-10}
command -v ctags >/dev/null || bash scripts/install-deps.sh universal-ctags >/dev/null
src=lib/src
if [[ -n $rev ]]; then
	tmp=$(mktemp -d)
	trap 'rm -rf "$tmp"' EXIT
	git archive "$rev" lib/src | tar -x -C "$tmp"
	src=$tmp/lib/src
fi

echo "Largest files of lib/src${rev:+ at $rev} (lines):"
find "$src" -name '*.cpp' -o -name '*.h' | xargs wc -l | grep -v ' total$' | sort -rn |
	head -n "$rows" | sed "s|$src/||"
echo
echo "Largest functions (lines):"
find "$src" -name '*.cpp' | xargs ctags -f - --c++-kinds=f --fields=+ne --output-format=u-ctags |
	awk -F'\t' '{ line = ""; end = ""
		for (i = 4; i <= NF; i++) {
			if ($i ~ /^line:/) line = substr($i, 6)
			if ($i ~ /^end:/) end = substr($i, 5)
		}
		if (line != "" && end != "") printf "%5d  %s  %s\n", end - line + 1, $1, $2 }' |
	sort -rn | head -n "$rows" | sed "s|$src/||"
