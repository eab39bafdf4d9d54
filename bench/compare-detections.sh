#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Are two revisions' detections byte-identical? Builds BASE and NEW (release, tools only) in
# build-compare/, runs calped-eval over the PETS 2009 S2L1 frames in every pyramid
# configuration that exists at the baseline, and compares the detection CSVs with cmp.
#   bash bench/compare-detections.sh [--base REV] [--new REV] [--frames N] [--jobs J]
#     --base REV   the reference revision (default 9a9077a, before the core's redesign)
#     --new  REV   the revision under test (default HEAD; uncommitted edits are not seen)
#     --frames N   only the first N of the 795 frames (default all)
#     --jobs J     calped-eval runs at a time (default 1); builds use CALPED_JOBS (default 2)
# Prints a table and writes it to out/compare/table.md; each run's CSVs, JSON and log are
# kept in out/compare/{base,new}/. Exit status: 0 all identical, 1 some configuration
# differs, 2 usage error, 3 a build or run failed, 130 interrupted. Without ../shared
# (CALPED_SHARED_DIR) there is no ground truth or calibration: it says so and exits 0
# without comparing.
# A revision is built once: build-compare/<commit>/ keeps its build and converted model, and
# later runs at the same commit reuse them (docs/benchmarks.md).
set -Eeuo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

me=compare-detections
# Anything that fails without being handled is a failed build or run, not a difference.
trap 'echo "$me: failed (line $LINENO: $BASH_COMMAND)" >&2; exit 3' ERR

usage() {
	sed -n '6,10s/^# \{0,1\}//p' "${BASH_SOURCE[0]}" >&2
}
usage_error() {
	echo "$me: $*" >&2
	usage
	exit 2
}

# --- The configurations ---------------------------------------------------------------
# name | calped-eval method | resize (as calped-eval names its CSVs) | where the resize is
# done (frame: the frame is resampled first; pyramid: inside the feature pyramid, the
# toolbox's nOctUp) | which levels the calibrated methods compute (toolbox: the toolbox's
# octaves; placed: levels placed among the needed ones; -: generic has no choice).
configs=(
	"generic-r1.0                 generic            1.0 frame   -"
	"generic-r2.0-frame           generic            2.0 frame   -"
	"generic-r2.0-pyramid         generic            2.0 pyramid -"
	"calibrated-octaves-r2.0-frame   calibrated      2.0 frame   toolbox"
	"calibrated-octaves-r2.0-pyramid calibrated      2.0 pyramid toolbox"
	"calibrated-placed-r1.5       calibrated         1.5 pyramid placed"
	"calibrated-placed-r2.0       calibrated         2.0 pyramid placed"
	"calibrated-placed-r2.5       calibrated         2.5 pyramid placed"
	"calibrated-static-placed-r2.0 calibrated-static 2.0 pyramid placed"
)

# --- Options ----------------------------------------------------------------------------
base_rev=9a9077a
new_rev=HEAD
frames=
jobs=1
while (($#)); do
	case $1 in
	--base | --new | --frames | --jobs)
		(($# >= 2)) || usage_error "$1 needs a value"
		case $1 in
		--base) base_rev=$2 ;;
		--new) new_rev=$2 ;;
		--frames) frames=$2 ;;
		--jobs) jobs=$2 ;;
		esac
		shift 2
		;;
	-h | --help)
		usage
		exit 0
		;;
	*) usage_error "unknown argument '$1'" ;;
	esac
done
if [[ -n $frames ]] && ! [[ $frames =~ ^[0-9]+$ && $frames -ge 1 && $frames -le 795 ]]; then
	usage_error "--frames must be a whole number from 1 to 795, got '$frames'"
fi
[[ $jobs =~ ^[0-9]+$ && $jobs -ge 1 && $jobs -le 64 ]] ||
	usage_error "--jobs must be a whole number from 1 to 64, got '$jobs'"

resolve() { # REV -> full commit hash; an unknown revision is a usage error
	git rev-parse --verify --quiet "$1^{commit}" || usage_error "unknown revision '$1'"
}
describe() { # commit -> short hash and the start of its subject
	local subject
	subject=$(git log -1 --format=%s "$1")
	((${#subject} <= 60)) || subject="${subject:0:57}..."
	echo "$(git rev-parse --short "$1") \"$subject\""
}

# (usage_error exits only the command substitution; pass its status on)
base=$(resolve "$base_rev") || exit 2
new=$(resolve "$new_rev") || exit 2

# --- Inputs -----------------------------------------------------------------------------
shared=${CALPED_SHARED_DIR:-../shared}
pets=$shared/data/pets2009-s2l1
gt=$pets/PETS2009-S2L1.xml
calib=$pets/View_001.xml
mat=$shared/models/dollar-toolbox/AcfInriaDetector.mat
for f in "$gt" "$calib" "$mat"; do
	if [[ ! -f $f ]]; then
		echo "$me: skipped: $f is absent (needs $shared: PETS ground truth, calibration and" \
			"Dollár's AcfInriaDetector.mat; set CALPED_SHARED_DIR)" >&2
		exit 0
	fi
done
bash scripts/fetch-pets.sh ${frames:+"$frames"}
frames_dir=data/pets/frames

# --- Building a revision ----------------------------------------------------------------
ninja_jobs=${CALPED_JOBS:-2}
meson_options=(-Dbuildtype=release -Dtests=false -Daravis=disabled -Dlibcamera=disabled)
targets=(tools/eval/calped-eval tools/detect/calped-detect tools/convert/calped-convert)
added_trees=()

remove_trees() {
	local t
	for t in "${added_trees[@]}"; do
		git worktree remove --force "$t" 2>/dev/null || rm -rf "$t"
	done
	git worktree prune
}
trap remove_trees EXIT
# An interrupted build must not leave its checkout registered: exit, so the EXIT trap runs.
trap 'echo "$me: interrupted" >&2; exit 130' INT TERM HUP

# Builds commit $1 in build-compare/<commit>/build, converts the model with that commit's own
# calped-convert (so a changed blob format is compared as its users would get it), and
# leaves build-compare/<commit>/done. A finished build is reused without a checkout.
build_revision() {
	local commit=$1
	local dir=build-compare/$commit
	local src=$dir/src build=$dir/build model=$dir/AcfInriaDetector.cpm
	if [[ -f $dir/done && -x $build/tools/eval/calped-eval && -f $model && ! $mat -nt $model ]]; then
		echo "$me: reusing the build of $(describe "$commit") in $dir"
		return
	fi
	echo "$me: building $(describe "$commit") in $dir (log: $dir/ninja.log)"
	rm -f "$dir/done"
	# A checkout left by an interrupted run is replaced: its files are older than the build's.
	if [[ -e $src ]]; then
		git worktree remove --force "$src" 2>/dev/null || rm -rf "$src"
		git worktree prune
	fi
	mkdir -p "$dir"
	rm -rf "$build"
	git worktree add --detach --quiet "$src" "$commit"
	added_trees+=("$src")
	meson setup "$build" "$src" "${meson_options[@]}" >"$dir/meson.log" 2>&1 || {
		tail -n 30 "$dir/meson.log" >&2
		false
	}
	ninja -C "$build" -j "$ninja_jobs" "${targets[@]}" >"$dir/ninja.log" 2>&1 || {
		grep -v '^\[[0-9]*/[0-9]*\]' "$dir/ninja.log" | tail -n 40 >&2
		false
	}
	"$build/tools/convert/calped-convert" "$mat" "$model.tmp" >/dev/null
	mv "$model.tmp" "$model"
	git worktree remove --force "$src"
	git worktree prune
	echo "$commit" >"$dir/done"
}

# --- Flags of a revision ----------------------------------------------------------------
# The redesigned calped-eval says where to resize (--resize-at frame|pyramid, default
# pyramid) and which levels to compute (--levels placed|toolbox, default placed, calibrated
# methods only); 9a9077a's adds --resize-in-pyramid and --calibrated-pyramid to a default of
# frame-resized toolbox octaves. Which one a revision has, its --help tells.
uses_new_flags() { # calped-eval
	local help
	help=$("$1" --help 2>&1 || true)
	[[ $help == *--resize-at* ]]
}

flags_for() { # new|old, resize-at, levels -> the pyramid flags, one a line
	local cli=$1 at=$2 levels=$3
	if [[ $cli == new ]]; then
		# Always explicit, so a change of the defaults cannot change the configuration.
		echo "--resize-at"
		echo "$at"
		if [[ $levels != - ]]; then
			echo "--levels"
			echo "$levels"
		fi
	else
		[[ $at == pyramid ]] && echo "--resize-in-pyramid"
		[[ $levels == placed ]] && echo "--calibrated-pyramid"
	fi
	return 0
}

# --- Running a revision -----------------------------------------------------------------
# Configurations of the same method and pyramid flags differ only by resize: one calped-eval
# call runs them all (--resizes 1.5,2.0,2.5), --jobs of them at a time. Groups are named by
# method, resize-at and levels; out/compare/<side>/<group>/ holds dets/, eval.json, the
# printed tables (eval.txt) and the log.
group_of() { # method, resize-at, levels
	echo "$1.$2.${3/-/any}"
}

run_revision() { # side (base|new), commit
	local side=$1 commit=$2
	local build=build-compare/$commit/build
	local eval=$build/tools/eval/calped-eval cli=old
	uses_new_flags "$eval" && cli=new
	echo "$me: $side $(git rev-parse --short "$commit"): calped-eval with the $cli pyramid flags"
	echo "$cli" >"$out/$side.cli"

	local -A resizes=()
	local order=() line name method resize at levels key
	for line in "${configs[@]}"; do
		read -r name method resize at levels <<<"$line"
		key="$method $at $levels"
		[[ -v resizes[$key] ]] || order+=("$key")
		resizes[$key]=${resizes[$key]:+${resizes[$key]},}$resize
	done

	for key in "${order[@]}"; do
		read -r method at levels <<<"$key"
		local dir=$out/$side/$(group_of "$method" "$at" "$levels")
		local flags=()
		mapfile -t flags < <(flags_for "$cli" "$at" "$levels")
		rm -rf "$dir"
		mkdir -p "$dir"
		local cmd=("$eval" --frames "$frames_dir" ${frames:+--max-frames "$frames"}
			--gt "$gt" --model "build-compare/$commit/AcfInriaDetector.cpm" --calib "$calib"
			--methods "$method" --resizes "${resizes[$key]}" "${flags[@]}" --jobs "$jobs"
			--json "$dir/eval.json" --dets "$dir/dets")
		echo "$me:   ${cmd[*]}"
		local start=$SECONDS
		"${cmd[@]}" >"$dir/eval.txt" 2>"$dir/eval.log" || {
			tail -n 20 "$dir/eval.log" >&2
			false
		}
		echo "$me:   $((SECONDS - start)) s"
	done
}

# --- Comparing --------------------------------------------------------------------------
rows() { # CSV -> detections (lines after the header)
	if [[ -f $1 ]]; then echo $(($(wc -l <"$1") - 1)); else echo missing; fi
}

frames_differing() { # CSV CSV -> frames whose detection lines are not the same
	awk -F, 'FNR == 1 { next }
		FILENAME == ARGV[1] { a[$1] = a[$1] $0 "\n"; next }
		{ b[$1] = b[$1] $0 "\n" }
		END {
			n = 0
			for (k in a) if (a[k] != b[k]) n++
			for (k in b) if (!(k in a)) n++
			print n
		}' "$1" "$2"
}

run_field() { # eval.json, method, resize, field -> the value, rounded for the table
	[[ -f $1 ]] || { echo -; return 0; }
	python3 - "$@" <<-'EOF'
		import json, sys
		path, method, resize, field = sys.argv[1:]
		for run in json.load(open(path)):
		    if run["method"] == method and abs(run["resize"] - float(resize)) < 1e-9:
		        v = run[field]
		        digits = {"fppf": 2, "wall_s": 1}.get(field, 3)
		        print("n/a" if v is None else f"{v:.{digits}f}")
		        break
		else:
		    print("-")
	EOF
}

# Fills $out/table.md; returns 1 when some configuration differs.
compare() {
	local line name method resize at levels same=0 differing=()
	local table=$out/table.md
	{
		echo "PETS 2009 S2L1 frames 1-${frames:-795}, calped-eval's detection CSVs of"
		echo
		echo "- base $(describe "$base") ($(<"$out/base.cli") pyramid flags)"
		echo "- new  $(describe "$new") ($(<"$out/new.cli") pyramid flags)"
		echo "- models converted by each: $(cmp -s "build-compare/$base/AcfInriaDetector.cpm" \
			"build-compare/$new/AcfInriaDetector.cpm" && echo identical || echo DIFFERENT)"
		echo
		echo "| configuration | base detections | new detections | identical | base s | new s |"
		echo "|---|---:|---:|---|---:|---:|"
		for line in "${configs[@]}"; do
			read -r name method resize at levels <<<"$line"
			local group csv_b csv_n json_b json_n verdict
			group=$(group_of "$method" "$at" "$levels")
			csv_b=$out/base/$group/dets/${method}_r$resize.csv
			csv_n=$out/new/$group/dets/${method}_r$resize.csv
			json_b=$out/base/$group/eval.json
			json_n=$out/new/$group/eval.json
			if [[ -f $csv_b && -f $csv_n ]] && cmp -s "$csv_b" "$csv_n"; then
				verdict=yes
				same=$((same + 1))
			else
				verdict=NO
				differing+=("$line")
			fi
			echo "| $name | $(rows "$csv_b") | $(rows "$csv_n") | $verdict |" \
				"$(run_field "$json_b" "$method" "$resize" wall_s) |" \
				"$(run_field "$json_n" "$method" "$resize" wall_s) |"
		done
		echo
		echo "$same of ${#configs[@]} configurations identical (cmp of the detection CSVs)."
		if ((${#differing[@]})); then
			echo
			echo "| differing configuration | frames differing | TPR base | TPR new | FPPF base | FPPF new | LAMR base | LAMR new |"
			echo "|---|---:|---:|---:|---:|---:|---:|---:|"
			for line in "${differing[@]}"; do
				read -r name method resize at levels <<<"$line"
				local group csv_b csv_n json_b json_n n f cells=()
				group=$(group_of "$method" "$at" "$levels")
				csv_b=$out/base/$group/dets/${method}_r$resize.csv
				csv_n=$out/new/$group/dets/${method}_r$resize.csv
				n=-
				[[ -f $csv_b && -f $csv_n ]] && n=$(frames_differing "$csv_b" "$csv_n")
				for f in tpr fppf log_avg_miss_rate; do
					cells+=("$(run_field "$out/base/$group/eval.json" "$method" "$resize" "$f")")
					cells+=("$(run_field "$out/new/$group/eval.json" "$method" "$resize" "$f")")
				done
				echo "| $name | $n | ${cells[0]} | ${cells[1]} | ${cells[2]} | ${cells[3]} |" \
					"${cells[4]} | ${cells[5]} |"
			done
		fi
		echo
		echo "base s, new s: calped-eval's wall time of the run (wall_s; $jobs run(s) at a time," \
			"on a machine that may be shared): informative only."
	} >"$table"
	((${#differing[@]} == 0))
}

# --- Main -------------------------------------------------------------------------------
if [[ $new == "$(git rev-parse HEAD)" ]] && ! git diff --quiet HEAD; then
	echo "$me: note: the working tree has uncommitted edits; NEW is commit $(git rev-parse --short HEAD) without them"
fi
start=$SECONDS
build_revision "$base"
[[ $new == "$base" ]] || build_revision "$new"

out=out/compare
rm -rf "$out"
mkdir -p "$out"
run_revision base "$base"
run_revision new "$new"

status=0
compare || status=1
echo
cat "$out/table.md"
echo
echo "$me: $((SECONDS - start)) s in all; table in $out/table.md"
exit "$status"
