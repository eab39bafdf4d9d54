#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# THE MAIN JOB: calibrated detection over the whole PETS 2009 S2L1 sequence (795 frames),
# with the camera's Tsai calibration (../shared/data/pets2009-s2l1/View_001.xml).
#   out/main/detections.csv   frame,x,y,w,h,score,ground_x,ground_y,world_height for every
#                             detection
#   out/main/frames.jsonl     one line per frame with the detector's time, and each
#                             detection's ground position and world height
#   out/main/overlays/        every 100th frame with the detections drawn
#   out/main/summary.txt      the table printed at the end
#   out/main/score.json       its detections scored against the ground truth (calped-eval
#                             --score-only: TPR, FPPF, log-average miss rate)
# calped-detect runs with its defaults and a calibration (the calibrated method, the resize
# chosen from the camera (2 for PETS) inside the pyramid, placed pyramid levels), with
# --reject-static: PETS is a fixed camera (docs/calibrated.md). A few minutes on a fresh machine, most of it the build.
# The long evaluation sweep (every method, resize and pyramid, docs/results.md) is
# scripts/run-eval-sweep.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

start=$SECONDS
# CALPED_BUILD_DIR picks another build folder.
builddir=${CALPED_BUILD_DIR:-build}
export CALPED_BUILD_DIR=$builddir
bash scripts/prepare-run.sh

out=out/main
model=models/AcfInriaDetector.cpm
frames=data/pets/frames
rm -rf "$out"
mkdir -p "$out"

calib=${CALPED_SHARED_DIR:-../shared}/data/pets2009-s2l1/View_001.xml
# The best configuration is calped-detect's default with a calibration: the calibrated
# method, the resize chosen from the camera and done inside the pyramid, computed levels
# placed among the needed ones; static-scene rejection is asked for, as it assumes a fixed
# camera (docs/calibrated.md, docs/cli.md).
cmd=("$builddir"/tools/detect/calped-detect --model "$model"
	--calib "$calib" --reject-static
	--csv "$out/detections.csv" --jsonl "$out/frames.jsonl"
	--overlay "$out/overlays" --overlay-every 100 "$frames")
echo "run-main: ${cmd[*]}"
# The tool's progress and closing summary line (stderr) are shown and kept.
"${cmd[@]}" 2>&1 | tee "$out/detect.log"

summary=$(grep '^calped-detect: summary:' "$out/detect.log" | tail -n 1)
resize=$(sed -n 's/^calped-detect: resize auto: \([^ ]*\) .*/\1/p' "$out/detect.log")
if [[ -z "$summary" ]]; then
	echo "run-main: calped-detect printed no summary line" >&2
	exit 1
fi
# "calped-detect: summary: frames=795 detections=... ms_median=..." -> value of one key
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$summary"; }

{
	echo "calped main job: PETS 2009 S2L1 view 1, AcfInriaDetector, calibrated with static-scene rejection, resize ${resize:-?} (chosen from the camera) inside the pyramid, placed levels"
	printf '  %-22s %s\n' \
		"frames" "$(field frames)" \
		"detections" "$(field detections)" \
		"detections per frame" "$(field per_frame)" \
		"ms/frame median" "$(field ms_median) (detector's own FrameStats::msTotal)" \
		"ms/frame mean" "$(field ms_mean)" \
		"wall time" "$(field wall_s) s for calped-detect, $((SECONDS - start)) s in all" \
		"CSV" "$out/detections.csv" \
		"per-frame records" "$out/frames.jsonl" \
		"overlays" "$out/overlays/ ($(find "$out/overlays" -name '*.png' | wc -l) images)" \
		"log" "$out/detect.log"
} | tee "$out/summary.txt"

# The result against the ground truth: the detections above, scored as calped-eval scores
# its own runs (docs/evaluation.md).
gt=${CALPED_SHARED_DIR:-../shared}/data/pets2009-s2l1/PETS2009-S2L1.xml
scmd=("$builddir"/tools/eval/calped-eval --score-only "$out/detections.csv" --gt "$gt"
	--frames "$frames" --label calibrated-static --json "$out/score.json")
echo "run-main: ${scmd[*]}"
{
	echo
	echo "against the ground truth ($gt):"
	"${scmd[@]}"
	echo
	echo "main job wall time: $((SECONDS - start)) s; the full evaluation: bash scripts/run-eval-sweep.sh"
} | tee -a "$out/summary.txt"

