#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Counts test cases in Meson's junit logs (BUILD/meson-logs/testlog.junit.xml).
# Prints "PASSED FAILED SKIPPED" summed over the files given.
#   scripts/count-junit.sh FILE...
set -euo pipefail

if (($# == 0)); then
	echo "0 0 0"
	exit 0
fi

# Meson writes the XML on one line, so split it into one tag per line first. A <testcase>
# fails if it holds <failure> or <error>, is skipped if it holds <skipped>, else passes.
cat "$@" | tr '<' '\n' | awk '
	/^testcase[ >\/]/ {
		if (open) count()
		open = 1; failed = 0; skipped = 0
		if ($0 ~ /\/>[[:space:]]*$/) { count() }
		next
	}
	open && /^(failure|error)[ >\/]/ { failed = 1 }
	open && /^skipped[ >\/]/ { skipped = 1 }
	open && /^\/testcase>/ { count() }
	function count() {
		if (failed) f++
		else if (skipped) s++
		else p++
		open = 0
	}
	END {
		if (open) count()
		printf "%d %d %d\n", p, f, s
	}'
