#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# THE MAIN JOB: the detector over the whole PETS 2009 S2L1 sequence (795 frames).
#   out/main/detections.csv   frame,x,y,w,h,score for every detection
#   out/main/frames.jsonl     one line per frame with the detector's time
#   out/main/overlays/        every 100th frame with the detections drawn
#   out/main/summary.txt      the table printed at the end
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

start=$SECONDS
bash scripts/install-deps.sh
bash scripts/build.sh build -Dbuildtype=release
bash scripts/setup-models.sh
bash scripts/fetch-pets.sh

out=out/main
model=models/AcfInriaDetector.cpm
frames=data/pets/frames
resize=2
rm -rf "$out"
mkdir -p "$out"

cmd=(build/tools/detect/calped-detect --model "$model" --resize "$resize"
	--csv "$out/detections.csv" --jsonl "$out/frames.jsonl"
	--overlay "$out/overlays" --overlay-every 100 "$frames")
echo "run-main: ${cmd[*]}"
# The tool's progress and closing summary line (stderr) are shown and kept.
"${cmd[@]}" 2>&1 | tee "$out/detect.log"

summary=$(grep '^calped-detect: summary:' "$out/detect.log" | tail -n 1)
if [[ -z "$summary" ]]; then
	echo "run-main: calped-detect printed no summary line" >&2
	exit 1
fi
# "calped-detect: summary: frames=795 detections=... ms_median=..." -> value of one key
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$summary"; }

{
	echo "calped main job: PETS 2009 S2L1 view 1, AcfInriaDetector, resize $resize"
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
