#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# THE EVALUATION SWEEP (long: about 15 minutes here; the main job is scripts/run-main.sh):
# calped-eval runs the generic, calibrated and calibrated-static methods at resizes 1.5,
# 2.0 and 2.5 over all 795 PETS 2009 S2L1 frames against the ground truth, first each frame
# resized and with the toolbox's octaves as the thesis does (--resize-at frame --levels
# toolbox), and writes
#   docs/results.md           tables, plots, machine, date and commit
#   docs/results/             the plots, and the sample frames it lists (docs/results/<run>/)
#   out/sweep/eval.json       one object per (method, resize); out/sweep/dets/ their CSVs
# then again with the resize inside the feature pyramid (--levels toolbox; tables in
# results.md, out/sweep/eval_in_pyramid.json, out/sweep/dets_in_pyramid/), and the calibrated
# methods with the defaults, placed pyramid levels (out/sweep/eval_placed.json,
# out/sweep/dets_placed/). docs/evaluation.md.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

start=$SECONDS
# CALPED_BUILD_DIR picks another build folder.
builddir=${CALPED_BUILD_DIR:-build}
export CALPED_BUILD_DIR=$builddir
bash scripts/prepare-run.sh

out=out/sweep
model=models/AcfInriaDetector.cpm
frames=data/pets/frames
rm -rf "$out"
mkdir -p "$out"

# Both modes; the calibrated one uses PETS view 1's Tsai calibration (calped-eval names and
# skips it if that file is missing).
eval_start=$SECONDS
pets=${CALPED_SHARED_DIR:-../shared}/data/pets2009-s2l1
gt=$pets/PETS2009-S2L1.xml
calib=()
if [[ -f $pets/View_001.xml ]]; then
	calib=(--calib "$pets/View_001.xml")
fi
# The same frames as above, decoded by an ffmpeg pipe: identical pixels (ffmpeg made the PNGs)
# for about 5 ms a frame where reading the PNGs back takes about 12, six runs over.
input=(--frames "$frames")
if [[ -s data/pets/vtest.avi ]]; then
	input=(--video data/pets/vtest.avi)
fi
results=docs/results
page=docs/results.md
# Each (method, resize) runs in its own process, one at a time by default: runs side by side
# share caches, memory bandwidth and (on small VMs) CPU time, and the ms/frame the table
# reports grows with them. CALPED_EVAL_JOBS=N trades that for wall time.
eval_jobs=${CALPED_EVAL_JOBS:-1}
mkdir -p "$results" "$out/plots"
find "$results" -maxdepth 2 -type f -name '*.png' -delete
# First as the thesis does it: each frame resized, then the toolbox's octaves.
ecmd=("$builddir"/tools/eval/calped-eval "${input[@]}" --gt "$gt" --model "$model" "${calib[@]}"
	--methods generic,calibrated,calibrated-static --resizes 1.5,2.0,2.5 --jobs "$eval_jobs"
	--resize-at frame --levels toolbox
	--json "$out/eval.json" --dets "$out/dets" --plots "$results" --overlays "$results"
	--overlay-frames 1,200,400,600 --markdown "$page.part")
echo "run-eval-sweep: ${ecmd[*]}"
"${ecmd[@]}" | tee "$out/eval.txt"
# The plots' data and gnuplot scripts are for redrawing, not for reading: keep them in out/.
find "$results" -maxdepth 1 -type f \( -name '*.dat' -o -name '*.gp' \) -exec mv -t "$out/plots" {} +
# The same runs with the resize done inside the feature pyramid (--resize-at pyramid, the
# default: the toolbox's nOctUp), still with the toolbox's octaves: tables only.
pcmd=("$builddir"/tools/eval/calped-eval "${input[@]}" --gt "$gt" --model "$model" "${calib[@]}"
	--methods generic,calibrated,calibrated-static --resizes 1.5,2.0,2.5 --jobs "$eval_jobs"
	--levels toolbox
	--json "$out/eval_in_pyramid.json" --dets "$out/dets_in_pyramid" --markdown "$page.pyramid")
echo "run-eval-sweep: ${pcmd[*]}"
"${pcmd[@]}" | tee "$out/eval_in_pyramid.txt"
# And with the defaults: computed levels placed among the needed ones (--levels placed,
# calibrated methods only), the resize inside the pyramid.
lcmd=("$builddir"/tools/eval/calped-eval "${input[@]}" --gt "$gt" --model "$model" "${calib[@]}"
	--methods calibrated,calibrated-static --resizes 1.5,2.0,2.5 --jobs "$eval_jobs"
	--json "$out/eval_placed.json" --dets "$out/dets_placed" --markdown "$page.placed")
echo "run-eval-sweep: ${lcmd[*]}"
"${lcmd[@]}" | tee "$out/eval_placed.txt"
eval_wall=$((SECONDS - eval_start))

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [[ $commit != unknown ]] && ! git diff --quiet HEAD 2>/dev/null; then
	commit="$commit (with uncommitted changes)"
fi
cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name:[[:space:]]*//p' | head -n 1)
{
	echo "<!-- SPDX-License-Identifier: BSD-2-Clause -->"
	echo "# Results: PETS 2009 S2L1"
	echo
	echo "Written by \`bash scripts/run-eval-sweep.sh\` (do not edit by hand) on $(date -u '+%Y-%m-%d %H:%M UTC'),"
	echo "commit \`$commit\`, on ${cpu:-an unknown CPU} with $(nproc) cores; runs at a time: $eval_jobs, each"
	echo "on one thread. calped-eval took $eval_wall s of wall time for all its runs over all frames."
	echo
	cat "$page.part"
	echo
	echo "## Resize inside the pyramid"
	echo
	echo "The same runs with the resize inside the pyramid (\`--resize-at pyramid\`, the default) and the"
	echo "toolbox's octaves (\`--levels toolbox\`): colour is converted at the frame's size and each"
	echo "computed level resampled from it (the toolbox's nOctUp) instead of the frame being resized"
	echo "first ([calibrated.md](calibrated.md#resize-inside-the-pyramid))."
	echo
	sed -e '/^Frames: /d' -e '/^### Plots/,$d' -e 's/^### /#### /' "$page.pyramid"
	echo
	echo "## Placed pyramid levels"
	echo
	echo "The calibrated methods with the defaults (resize inside the pyramid, \`--levels placed\`): channels"
	echo "computed at levels placed among the needed ones instead of the toolbox's octaves"
	echo "([calibrated.md](calibrated.md#placed-pyramid-levels)). Compare the ms/frame with the"
	echo "generic mode of the first table."
	echo
	sed -e '/^Frames: /d' -e '/^### Plots/,$d' -e 's/^### /#### /' "$page.placed"
} >"$page"
rm -f "$page.part" "$page.pyramid" "$page.placed"

{
	echo
	echo "evaluation (calped-eval, $eval_wall s wall time, runs at a time: $eval_jobs): $page, $out/eval.json"
	cat "$out/eval.txt"
	echo
	echo "resize inside the pyramid: $out/eval_in_pyramid.json"
	cat "$out/eval_in_pyramid.txt"
	echo
	echo "placed pyramid levels: $out/eval_placed.json"
	cat "$out/eval_placed.txt"
	echo
	echo "sweep wall time: $((SECONDS - start)) s"
} | tee "$out/summary.txt"
