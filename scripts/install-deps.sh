#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Installs every Debian 12 package that building, testing and the main job need.
# Fast when everything is already there: apt is only called for missing packages.
#   scripts/install-deps.sh [EXTRA_PACKAGE...]   (scripts/fuzz.sh adds clang-14 and friends)
set -euo pipefail

packages=(
	ca-certificates
	g++
	meson
	ninja-build
	pkg-config
	libeigen3-dev
	libmatio-dev
	libstb-dev
	libgtest-dev
	# the Python binding's tests (tests/python)
	python3-numpy
	python3-pytest
	libexpat1-dev
	ffmpeg
	gnuplot-nox
	valgrind
	libaravis-dev
	libusb-1.0-0-dev
	aravis-tools
	libcamera-dev
	# The GStreamer element (gstreamer/) and its tests: headers, gst-inspect-1.0 and
	# gst-launch-1.0, and the plugins that decode the PETS video (avidemux, avdec_msmpeg4).
	libgstreamer1.0-dev
	libgstreamer-plugins-base1.0-dev
	gstreamer1.0-tools
	gstreamer1.0-plugins-base
	gstreamer1.0-plugins-good
	gstreamer1.0-libav
	# MQTT publishing (mqtt/) and its tests against a real broker (tests/mqtt); paho for
	# the fleet's ground-plan subscriber (examples/fleet)
	libmosquitto-dev
	mosquitto
	mosquitto-clients
	python3-paho-mqtt
)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
	status=$(dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null || true)
	if [[ "$status" != ii* ]]; then
		missing+=("$p")
	fi
done

if ((${#missing[@]} == 0)); then
	echo "install-deps: all ${#packages[@]} packages already installed"
	exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
	echo "install-deps: missing packages: ${missing[*]}" >&2
	echo "install-deps: run as root (or: sudo apt-get install ${missing[*]})" >&2
	exit 1
fi

export DEBIAN_FRONTEND=noninteractive
echo "install-deps: installing ${missing[*]}"
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
echo "install-deps: done"
