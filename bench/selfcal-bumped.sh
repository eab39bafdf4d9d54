#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# `--calib auto` through a bumped camera, end to end through calped-detect's JSON records
# (docs/calibration.md, "A bumped camera"): PETS frames 1-795 cropped to 640x420, the window
# at (0, 0) up to frame BUMP (default 300) and at (128, 156) after it (the scene jumps up and
# left: the camera was bumped). Prints every change of (method, camera_estimate) in the
# records and calped-detect's estimate lines; writes out/selfcal-bumped/.
#   bash bench/selfcal-bumped.sh [BUILDDIR] [BUMP]     (needs ffmpeg, data/pets/frames, the model)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
bump=${2:-300}
frames=data/pets/frames
model=models/AcfInriaDetector.cpm
out=out/selfcal-bumped
for f in "$frames/000795.png" "$model" "$build/tools/detect/calped-detect"; do
	[[ -e $f ]] || { echo "selfcal-bumped: missing $f" >&2; exit 1; }
done
command -v ffmpeg >/dev/null || { echo "selfcal-bumped: needs ffmpeg" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out/frames"
# Frame k keeps its number: before the bump cropped at (0, 0), after it at (128, 156).
ffmpeg -nostdin -loglevel error -start_number 1 -i "$frames/%06d.png" -frames:v "$bump" \
	-vf crop=640:420:0:0 -start_number 1 "$out/frames/%06d.png"
ffmpeg -nostdin -loglevel error -start_number $((bump + 1)) -i "$frames/%06d.png" \
	-vf crop=640:420:128:156 -start_number $((bump + 1)) "$out/frames/%06d.png"

"$build/tools/detect/calped-detect" --model "$model" --calib auto --jsonl "$out/records.jsonl" \
	"$out/frames" 2>"$out/detect.log"
grep 'calib auto' "$out/detect.log" || true
echo "bumped after frame $bump; the records where (method, camera_estimate) changes:"
python3 - "$out/records.jsonl" <<'PY'
import json, sys
last = None
for line in open(sys.argv[1]):
    r = json.loads(line)
    state = (r["method"], r["camera_estimate"])
    if state != last:
        print(f'frame {r["frame"]}: method {state[0]}, camera_estimate {state[1]}')
        last = state
PY
