#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# What every run over PETS needs first: the Debian packages, a release build in
# $CALPED_BUILD_DIR (default build), the converted INRIA model and the 795 PETS frames.
# Used by scripts/run-main.sh and scripts/run-eval-sweep.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

export CALPED_BUILD_DIR=${CALPED_BUILD_DIR:-build}
bash scripts/install-deps.sh
bash scripts/build.sh "$CALPED_BUILD_DIR" -Dbuildtype=release
bash scripts/setup-models.sh
bash scripts/fetch-pets.sh
