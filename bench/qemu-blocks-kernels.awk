# SPDX-License-Identifier: BSD-2-Clause
# The qemu plugin's "ADDRESS INSTRUCTIONS" lines (toolchains/qemu-insn-profile.c) ->
# "kernel <tab> instructions" lines and "total <tab> N" (bench/arm-kernel-shares.sh; run
# with -f bench/kernel-name.awk). syms: the program's functions as "START SIZE NAME" (hex,
# sorted by START, from nm -n -S -C); base: where qemu loaded the program. Blocks outside
# the program's functions (the C library) count as "other".
function hex(s,   i, v) {
	v = 0; s = tolower(s)
	for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
	return v
}
BEGIN {
	while ((getline line < syms) > 0) {
		split(line, f, " "); n++
		start[n] = hex(f[1]); end[n] = start[n] + hex(f[2])
		sub(/^[^ ]+ [^ ]+ /, "", line); name[n] = line
	}
}
{
	off = hex($1) - base
	lo = 1; hi = n; k = 0
	while (lo <= hi) { mid = int((lo + hi) / 2); if (start[mid] <= off) { k = mid; lo = mid + 1 } else hi = mid - 1 }
	sum[(k > 0 && off < end[k]) ? kernelOf(name[k]) : "other"] += $2
	total += $2
}
END { for (k in sum) print k "\t" sum[k]; print "total\t" total }
