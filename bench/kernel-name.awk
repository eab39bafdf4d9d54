# SPDX-License-Identifier: BSD-2-Clause
# kernelOf(f): the kernel a function belongs to, for bench/kernel-shares.sh and
# bench/arm-kernel-shares.sh: kernels by name without their build suffix, their helpers
# (the resamplers' passes and plans, the histograms' sums) as the kernel, the trees' scans
# (the generic grid or the calibrated lists) as "trees", anything else as "other". f is a
# demangled name, with or without its parameter list.
function kernelOf(f,   k) {
	gsub(/\(anonymous namespace\)::/, "", f)
	sub(/\(.*/, "", f)
	while (f ~ /<[^<>]*>/) gsub(/<[^<>]*>/, "", f)
	if (f !~ /calped::kernels::/) return "other"
	k = f; sub(/.*::/, "", k); sub(/_(ref|opt|avx2|neon)$/, "", k)
	if (k ~ /^(columnPass|planPairs|planBlock|planWindow|planChunk|rowPass|rowPassChunk|windowRows|pairBlockRows|resamplePlane)$/) k = "resamplePlanes"
	if (k == "sumEightPixels" || k == "hist6") k = "gradHist4"
	if (k ~ /^scan/) k = "trees"
	return k == "" ? "other" : k
}
