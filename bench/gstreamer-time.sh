#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# The calped GStreamer element's time per frame against calped's own (docs/gstreamer.md):
#   bench/gstreamer-time.sh [BUILDDIR] [FRAMES]      (defaults: build, 795 = all of vtest.avi)
# For each of NV12 and RGB it runs
#   filesrc vtest.avi ! decodebin ! videoconvert ! FORMAT ! calped (calibration, resize 2) ! fakesink
# and averages the element's messages: "ms" (the detector's FrameStats::msTotal inside the
# element) and "ms-element" (the whole transform: mapping, detection, metas); then the same
# pipeline without calped (decoding and conversion only) for the wall time the element adds;
# then calped-detect with the same configuration over data/pets/frames (ffmpeg's PNGs of
# the same video), whose ms_mean is FrameStats::msTotal outside GStreamer.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

builddir=${1:-build}
frames=${2:-795}
model=${CALPED_MODEL:-models/AcfInriaDetector.cpm}
calib=${CALPED_CALIB:-../shared/data/pets2009-s2l1/View_001.xml}
video=data/pets/vtest.avi
for f in "$model" "$calib" "$video" "$builddir/gstreamer/libgstcalped.so"; do
	[[ -e $f ]] || { echo "gstreamer-time: missing $f" >&2; exit 1; }
done
export GST_PLUGIN_PATH=$PWD/$builddir/gstreamer
export GST_REGISTRY=$PWD/$builddir/gstreamer/bench-registry.bin

source_part() {
	# identity passes N - 1 buffers, then ends the stream
	echo "filesrc location=$video ! decodebin ! videoconvert ! video/x-raw,format=$1 ! identity eos-after=$((frames + 1))"
}

for format in NV12 RGB; do
	start=$(date +%s.%N)
	# shellcheck disable=SC2046 # the pipeline is words
	gst-launch-1.0 -m $(source_part "$format") ! calped model="$model" calibration="$calib" resize=2 \
		! fakesink 2>&1 | awk -v format="$format" '
		/calped-detections/ {
			n++
			match($0, /ms=\(double\)[0-9.e+-]+/); ms += substr($0, RSTART + 11, RLENGTH - 11)
			match($0, /ms-element=\(double\)[0-9.e+-]+/); el += substr($0, RSTART + 19, RLENGTH - 19)
			match($0, /count=\(int\)[0-9]+/); dets += substr($0, RSTART + 11, RLENGTH - 11)
		}
		END { printf "%s: %d frames, %d detections, element %.2f ms/frame, its detector (FrameStats::msTotal) %.2f ms/frame\n", format, n, dets, el / n, ms / n }'
	with=$(echo "$(date +%s.%N) - $start" | bc)
	start=$(date +%s.%N)
	# shellcheck disable=SC2046
	gst-launch-1.0 -q $(source_part "$format") ! fakesink
	without=$(echo "$(date +%s.%N) - $start" | bc)
	echo "$format: pipeline wall time $with s with calped, $without s without (decode and convert)"
done

detect=$builddir/tools/detect/calped-detect
if [[ -x $detect ]]; then
	"$detect" --model "$model" --calib "$calib" --method calibrated --resize 2 --resize-in-pyramid \
		--calibrated-pyramid --max-frames "$frames" --quiet --jsonl - data/pets/frames |
		awk '{ match($0, /"ms":[0-9.]+/); ms += substr($0, RSTART + 5, RLENGTH - 5); n++ }
		END { printf "calped-detect over the PNG frames: %d frames, FrameStats::msTotal %.2f ms/frame\n", n, ms / n }'
fi
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
