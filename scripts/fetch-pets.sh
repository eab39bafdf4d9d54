#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Gets PETS 2009 S2L1 view 1 (Debian opencv-doc's vtest.avi) and decodes it to
#   data/pets/frames/000001.png ... 000795.png
# Frame 1 is the first decoded frame = annotation frame number 0 (see ../shared/README.md).
# PNG keeps the decoded pixels exact. With N, only the first N frames are needed.
#   scripts/fetch-pets.sh [N]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

total=795
want=${1:-$total}
if ! [[ "$want" =~ ^[0-9]+$ ]] || ((want < 1 || want > total)); then
	echo "fetch-pets: N must be a whole number from 1 to $total, got '$want'" >&2
	exit 2
fi

dir=data/pets
frames=$dir/frames
avi=$dir/vtest.avi

count_frames() {
	if [[ -d "$frames" ]]; then
		find "$frames" -maxdepth 1 -name '[0-9][0-9][0-9][0-9][0-9][0-9].png' | wc -l
	else
		echo 0
	fi
}

have=$(count_frames)
if ((have >= want)); then
	echo "fetch-pets: $frames already holds $have frames"
	exit 0
fi

mkdir -p "$dir"
if [[ ! -s "$avi" ]]; then
	for tool in apt-get dpkg; do
		command -v "$tool" >/dev/null || { echo "fetch-pets: needs $tool (Debian)" >&2; exit 1; }
	done
	if ! compgen -G "$dir/opencv-doc_*.deb" >/dev/null; then
		echo "fetch-pets: apt-get download opencv-doc (about 96 MB) into $dir"
		if ! (cd "$dir" && apt-get download -q opencv-doc </dev/null); then
			echo "fetch-pets: refreshing the package lists and retrying"
			apt-get update -q </dev/null
			(cd "$dir" && apt-get download -q opencv-doc </dev/null) || {
				echo "fetch-pets: could not download opencv-doc with apt-get" >&2
				exit 1
			}
		fi
	fi
	debs=("$dir"/opencv-doc_*.deb)
	echo "fetch-pets: extracting ${debs[0]}"
	rm -rf "$dir/opencv-doc"
	dpkg -x "${debs[0]}" "$dir/opencv-doc"
	found=$(find "$dir/opencv-doc" -path '*examples/data/vtest.avi' -print -quit)
	if [[ -z "$found" ]]; then
		echo "fetch-pets: ${debs[0]} has no examples/data/vtest.avi" >&2
		exit 1
	fi
	cp "$found" "$avi.tmp"
	mv "$avi.tmp" "$avi"
	# The rest of the package is 270 MB of other documentation; the video is all we keep.
	rm -rf "$dir/opencv-doc" "${debs[@]}"
fi
# The video of opencv-doc 4.6.0+dfsg-12, from which ../shared's reference outputs were made.
expected_sha=45cddc9490be69345cbdab64ca583be65987e864ca408038e648db99e10516cf
sha=$(sha256sum "$avi" | cut -d' ' -f1)
if [[ "$sha" != "$expected_sha" ]]; then
	echo "fetch-pets: warning: $avi sha256 is $sha, not $expected_sha;" \
		"results may differ from ../shared/reference" >&2
fi

command -v ffmpeg >/dev/null || { echo "fetch-pets: needs ffmpeg (bash scripts/install-deps.sh)" >&2; exit 1; }
# Decode into a fresh folder so an interrupted run never looks complete.
tmp=$dir/frames.tmp
rm -rf "$tmp"
mkdir -p "$tmp"
limit=()
if ((want < total)); then
	limit=(-frames:v "$want")
fi
echo "fetch-pets: decoding $avi to $frames/%06d.png ($want frames)"
ffmpeg -nostdin -loglevel error -i "$avi" "${limit[@]}" -start_number 1 "$tmp/%06d.png"
rm -rf "$frames"
mv "$tmp" "$frames"

have=$(count_frames)
if ((have < want)); then
	echo "fetch-pets: decoded only $have frames, expected $want" >&2
	exit 1
fi
echo "fetch-pets: ready: $have frames in $frames"
