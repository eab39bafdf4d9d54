#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Cross-builds calped for an ARM target and runs its test suite under qemu-user:
#   scripts/cross-test.sh aarch64|armhf [meson options...]
#   e.g. scripts/cross-test.sh aarch64 --cross-file toolchains/board-cortex-a53.ini
# 1. installs (apt, only what is missing) the cross compiler, qemu-user and the target's
#    multiarch stb and GoogleTest (Debian arch arm64 or armhf);
# 2. builds calped-convert for the build machine (build-cross-host/, unless CALPED_CONVERT
#    names one): the target has no libmatio, and models are converted off the camera anyway;
# 3. cross-builds the core, the tools stb allows and the tests in build-TARGET/;
# 4. registers qemu-user with binfmt_misc (if no handler is there) so that the programs the
#    tests start (calped-detect, calped-calibrate, calped-eval) run too;
# 5. runs `meson test`, each test through the cross file's exe_wrapper (qemu-user), and ends
#    with "N passed, N failed[, N skipped]", counting GoogleTest cases in the junit log.
#    By default the program-level suites (tools, ports, eval, packaging) are built but not
#    run under emulation; CALPED_CROSS_SUITES=all runs them too.
# Environment: CALPED_JOBS (default 2), CALPED_CONVERT (a host calped-convert to use),
# CALPED_CROSS_SUITES (default: the target-dependent suites; all: every suite),
# CALPED_CROSS_TIMEOUT_MULTIPLIER (meson test timeouts under emulation, default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
	echo "usage: scripts/cross-test.sh aarch64|armhf [meson options...]" >&2
	exit 2
}
(($# >= 1)) || usage
target=$1
shift
case "$target" in
aarch64)
	triplet=aarch64-linux-gnu
	debarch=arm64
	qemu=qemu-aarch64
	elf_class=02   # ELFCLASS64
	elf_machine=b7 # EM_AARCH64
	;;
armhf)
	triplet=arm-linux-gnueabihf
	debarch=armhf
	qemu=qemu-arm
	elf_class=01   # ELFCLASS32
	elf_machine=28 # EM_ARM
	;;
*) usage ;;
esac

start=$SECONDS
jobs=${CALPED_JOBS:-2}
builddir=build-$target
crossfile=toolchains/$triplet.ini
say() { echo "cross-test[$target]: $*"; }

# ---- 1. packages --------------------------------------------------------------------------
bash scripts/install-deps.sh

is_installed() {
	[[ "$(dpkg-query -W -f='${db:Status-Abbrev}' "$1" 2>/dev/null || true)" == ii* ]]
}
packages=("g++-$triplet" qemu-user "libstb-dev:$debarch" "libgtest-dev:$debarch")
missing=()
for p in "${packages[@]}"; do
	is_installed "$p" || missing+=("$p")
done
if ((${#missing[@]} > 0)); then
	if [[ $(id -u) -ne 0 ]]; then
		say "missing packages: ${missing[*]}; run as root (or: sudo dpkg --add-architecture" \
			"$debarch && sudo apt-get update && sudo apt-get install ${missing[*]})" >&2
		exit 1
	fi
	export DEBIAN_FRONTEND=noninteractive
	if ! dpkg --print-foreign-architectures | grep -qx "$debarch"; then
		say "dpkg --add-architecture $debarch (multiarch: the target's libraries beside the host's)"
		dpkg --add-architecture "$debarch"
	fi
	say "apt-get update"
	# A mirror that is mid-sync fails one index while the rest are fine: install decides.
	apt-get update -q </dev/null || say "warning: apt-get update reported errors; trying the install anyway" >&2
	say "apt-get install ${missing[*]}"
	apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
fi

# The parity tests need PETS frames 1-50; like scripts/run-tests.sh, a failed download
# makes them skip, loudly.
if ! bash scripts/fetch-pets.sh 50; then
	say "WARNING: no PETS frames; the tests that need them will be skipped" >&2
fi

# ---- 2. calped-convert for the build machine ----------------------------------------------
convert=${CALPED_CONVERT:-}
if [[ -z "$convert" ]]; then
	hostdir=build-cross-host
	if [[ ! -f "$hostdir/meson-private/coredata.dat" ]]; then
		say "configuring $hostdir (calped-convert for the build machine)"
		meson setup "$hostdir" -Dbuildtype=release -Dtests=false -Dtools=enabled
	fi
	say "ninja -C $hostdir tools/convert/calped-convert"
	ninja -C "$hostdir" -j "$jobs" tools/convert/calped-convert
	convert=$PWD/$hostdir/tools/convert/calped-convert
fi
[[ -x "$convert" ]] || { say "no calped-convert at $convert" >&2; exit 1; }
convert=$(cd "$(dirname "$convert")" && pwd)/$(basename "$convert")
say "model converter (build machine): $convert"

# ---- 3. cross build -----------------------------------------------------------------------
setup_args=(--cross-file "$crossfile" -Dbuildtype=release -Dtests=true "$@")
# Meson reads cross files only when a folder is set up: a change of the arguments or of
# any toolchains/*.ini sets the folder up afresh.
stamp=$builddir/.cross-test-setup
setup_id="${setup_args[*]} $(cat toolchains/*.ini | sha256sum | cut -c1-16)"
if [[ -f "$builddir/meson-private/coredata.dat" && -f "$stamp" &&
	"$(cat "$stamp")" == "$setup_id" ]]; then
	say "reconfiguring $builddir"
	meson setup --reconfigure "$builddir"
else
	wipe=()
	[[ -f "$builddir/meson-private/coredata.dat" ]] && wipe=(--wipe)
	say "meson setup ${wipe[*]} $builddir ${setup_args[*]}"
	meson setup "${wipe[@]}" "$builddir" "${setup_args[@]}"
	echo "$setup_id" >"$stamp"
fi
say "ninja -C $builddir -j $jobs"
ninja -C "$builddir" -j "$jobs"

# Without libmatio for the target there is no cross-built calped-convert. The CLI tests look
# for one at this path and skip their valid runs without it: give them the host's.
cross_convert=$builddir/tools/convert/calped-convert
if [[ ! -e "$cross_convert" || -L "$cross_convert" ]]; then
	mkdir -p "$(dirname "$cross_convert")"
	ln -sfn "$convert" "$cross_convert"
fi
# The core, model and eval tests convert the model with $CALPED_CONVERT when their build
# has no converter; a host program started from an emulated one runs natively.
export CALPED_CONVERT=$convert

# ---- 4. binfmt_misc -----------------------------------------------------------------------
# exe_wrapper runs each test under qemu; the target programs a test starts need the kernel
# to hand foreign ELF files to qemu as well. Any enabled handler for this ELF machine will do.
binfmt=/proc/sys/fs/binfmt_misc
# The ELF header up to e_machine: class, little-endian, version 1, any OS ABI, executable or
# shared object (PIE), and the target's machine.
ident_pad=0000000000000000 # EI_ABIVERSION and padding
magic=7f454c46${elf_class}010100${ident_pad}0200${elf_machine}00
mask=ffffffffffffff00fffffffffffffffffeffffff
hex_escape() { sed 's/../\\x&/g' <<<"$1"; }
binfmt_ready() {
	local f
	for f in "$binfmt"/*; do
		[[ -f "$f" && "$(basename "$f")" != register && "$(basename "$f")" != status ]] || continue
		if grep -qx enabled "$f" && grep -qx "magic $magic" "$f"; then
			say "binfmt_misc: $(basename "$f") runs $target programs ($(sed -n 's/^interpreter //p' "$f"))"
			return 0
		fi
	done
	return 1
}
if [[ ! -e "$binfmt/register" ]]; then
	mount -t binfmt_misc binfmt_misc "$binfmt" 2>/dev/null || true
fi
if ! binfmt_ready; then
	name=calped-$qemu
	if [[ -w "$binfmt/register" ]] &&
		echo ":$name:M::$(hex_escape "$magic"):$(hex_escape "$mask"):$(command -v "$qemu"):" >"$binfmt/register" 2>/dev/null; then
		say "binfmt_misc: registered $name (stays until reboot; remove: echo -1 > $binfmt/$name)"
	else
		say "WARNING: cannot register $qemu with binfmt_misc (needs root and binfmt_misc);" \
			"the tests that start calped-detect, calped-calibrate or calped-eval will fail" >&2
	fi
fi

# ---- 5. tests -----------------------------------------------------------------------------
log=$builddir/meson-logs/testlog.junit.xml
rm -f "$log"
# gtest leaves NAME.xml beside each test; a stale one must not stand in for a crash.
find "$builddir" -maxdepth 1 -name '*.xml' -delete
multiplier=${CALPED_CROSS_TIMEOUT_MULTIPLIER:-2}
# What runs under emulation: the tests whose outcome can depend on the target (the kernels
# against their references, fixed-point parity with the toolbox, the detector, model and
# calibration code, self-calibration, the C API, the parsers on the fuzz regressions). The
# program-level suites (tools, ports, eval, packaging) drive the same library through
# calped-detect and friends: on the host they catch what they are for, and under qemu they
# cost most of the emulated time (docs/testing.md). They are still cross-compiled above.
# CALPED_CROSS_SUITES=all runs everything.
suite_args=()
if [[ ${CALPED_CROSS_SUITES:-target} != all ]]; then
	for s in tools ports eval packaging; do
		suite_args+=(--no-suite "$s")
	done
fi
say "meson test -C $builddir ${suite_args[*]} (under $qemu)"
test_rc=0
meson test -C "$builddir" --print-errorlogs --num-processes "$jobs" --no-rebuild \
	--timeout-multiplier "$multiplier" "${suite_args[@]}" || test_rc=$?

passed=0 failed=0 skipped=0
if [[ -f "$log" ]]; then
	read -r passed failed skipped < <(bash scripts/count-junit.sh "$log")
else
	say "no junit log ($log)" >&2
	test_rc=1
fi
# A test executable can fail without a failing case (a crash before gtest wrote its XML).
if ((test_rc != 0 && failed == 0)); then
	failed=1
fi
say "wall time $((SECONDS - start)) s"
rc=0
if ((failed > 0)); then
	rc=1
elif ((passed == 0)); then
	say "no test ran"
	rc=1
fi
if ((skipped > 0)); then
	echo "$passed passed, $failed failed, $skipped skipped"
else
	echo "$passed passed, $failed failed"
fi
exit $rc
