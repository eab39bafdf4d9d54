#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# The peer side by side: OpenCV's HOG people detector and calped on the same PETS frames,
# scored by the same matcher (bench/hog_peer.py; docs/evaluation.md, "Peer comparison").
# Installs python3-opencv (this script's dependency only), builds calped-eval if needed,
# converts the model and decodes PETS like the main job. Results in out/peer/.
#   bash bench/run-peer.sh [hog_peer.py options...]     e.g. --max-frames 0 for all 795 frames
# CALPED_BUILD_DIR picks the build folder (default build).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

builddir=${CALPED_BUILD_DIR:-build}
export CALPED_BUILD_DIR=$builddir
shared=${CALPED_SHARED_DIR:-../shared}

status=$(dpkg-query -W -f='${db:Status-Abbrev}' python3-opencv 2>/dev/null || true)
if [[ "$status" != ii* ]]; then
	if [[ $(id -u) -ne 0 ]]; then
		echo "run-peer: python3-opencv is missing; run as root (or: sudo apt-get install python3-opencv)" >&2
		exit 1
	fi
	echo "run-peer: installing python3-opencv"
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -q
	apt-get install -y -q --no-install-recommends python3-opencv </dev/null
fi

evaluator=$builddir/tools/eval/calped-eval
if [[ ! -x "$evaluator" ]]; then
	bash scripts/build.sh "$builddir" -Dbuildtype=release
fi
bash scripts/setup-models.sh
bash scripts/fetch-pets.sh

# Debian's OpenCV is for Debian's python, whatever python3 comes first on the PATH.
/usr/bin/python3 bench/hog_peer.py --frames data/pets/frames \
	--gt "$shared/data/pets2009-s2l1/PETS2009-S2L1.xml" \
	--model models/AcfInriaDetector.cpm --eval "$evaluator" --out out/peer "$@"
