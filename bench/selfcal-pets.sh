#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Self-calibration on PETS 2009 S2L1 against the Tsai calibration (docs/calibration.md,
# "Self-calibration on PETS"): calped-autocalib on frames 1-N (N = 50 100 200 300) at
# resize 2, then calped-eval's calibrated method over all 795 frames at resize 2 with
# View_001.xml and with the 300-frame estimate. Prints the tables; writes out/selfcal-pets/.
#   bash bench/selfcal-pets.sh [BUILDDIR]      (default build; needs calped-autocalib, calped-eval)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
frames=data/pets/frames
model=models/AcfInriaDetector.cpm
truth=../shared/data/pets2009-s2l1/View_001.xml
gt=../shared/data/pets2009-s2l1/PETS2009-S2L1.xml
out=out/selfcal-pets
for f in "$frames/000001.png" "$model" "$truth" "$gt" "$build/tools/autocalib/calped-autocalib" "$build/tools/eval/calped-eval"; do
	[[ -e $f ]] || { echo "selfcal-pets: missing $f" >&2; exit 1; }
done
mkdir -p "$out"

echo "| frames | verdict | focal px | tilt deg | height m | horizon row | observations | inliers | residual | errors vs Tsai |"
echo "|---:|---|---:|---:|---:|---:|---:|---:|---:|---|"
for n in 50 100 200 300; do
	log=$out/autocalib-$n.log
	if "$build/tools/autocalib/calped-autocalib" --model "$model" --frames "$frames" --resize 2 \
		--max-frames "$n" -o "$out/camera-$n.yaml" --compare-to "$truth" >"$log" 2>&1; then
		python3 - "$log" "$n" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
def g(pattern):
    return re.search(pattern, t).group(1)
cells = [sys.argv[2], "Ok", g(r"focal (\S+ \+- \S+) px"), g(r"tilt (\S+ \+- \S+) deg"),
         g(r"height (\S+ \+- \S+) m"), g(r"horizon row (\S+) at"), g(r"(\d+) observations"),
         g(r"(\d+) inliers"), g(r"residual (\S+)"), g(r"error: (.*)")]
print("| " + " | ".join(cells) + " |")
PY
	else
		echo "| $n | $(sed -n 's/.*cannot calibrate (\([A-Za-z]*\).*/\1/p' "$log") | | | | | | | | $(sed 's/|/\\|/g' "$log" | tr -d '\n' | cut -c1-160) |"
	fi
done
echo
echo "| camera | LAMR | CApF | TPR | FPPF |"
echo "|---|---:|---:|---:|---:|"
for cam in tsai self; do
	calib=$truth
	[[ $cam == self ]] && calib=$out/camera-300.yaml
	[[ -e $calib ]] || { echo "| $cam | (no camera) | | | |"; continue; }
	"$build/tools/eval/calped-eval" --frames "$frames" --gt "$gt" --model "$model" --calib "$calib" \
		--methods calibrated --resizes 2.0 --json "$out/eval-$cam.json" --quiet >"$out/eval-$cam.log" 2>&1
	awk -F'|' -v c="$cam" '/^\| calibrated/ { gsub(/ /, ""); print "| " c " | " $9 " | " $5 " | " $6 " | " $7 " |"; exit }' "$out/eval-$cam.log"
done
