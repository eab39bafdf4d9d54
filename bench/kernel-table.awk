# SPDX-License-Identifier: BSD-2-Clause
# The table of bench/kernel-shares.sh and bench/arm-kernel-shares.sh from two files of
# "kernel <tab> instructions per frame" (calibrated, then generic; "total" among them):
# M instructions, shares and the calibrated/generic ratio, largest generic cost first,
# kernels under 0.5% of both together as "(the rest)". label names the calibrated column.
BEGIN {
	FS = "\t"
	printf "| kernel | %s | share | generic | share | ratio |\n", label
	print "|---|---:|---:|---:|---:|---:|"
}
FNR == 1 { file++ }
file == 1 { c[$1] = $2; keys[$1] = 1 }
file == 2 { g[$1] = $2; keys[$1] = 1 }
END {
	ct = c["total"]; gt = g["total"]
	for (k in keys) if (k != "total") order[n++] = k
	for (i = 0; i < n; i++) for (j = i + 1; j < n; j++)
		if (g[order[j]] > g[order[i]]) { t = order[i]; order[i] = order[j]; order[j] = t }
	for (i = 0; i < n; i++) {
		k = order[i]
		if (c[k] + g[k] < 0.005 * (ct + gt)) { oc += c[k]; og += g[k]; continue }
		printf "| %s | %.1f | %.1f%% | %.1f | %.1f%% | %s |\n", k, c[k] / 1e6, 100 * c[k] / ct,
			g[k] / 1e6, 100 * g[k] / gt, (g[k] > 0 ? sprintf("%.2f", c[k] / g[k]) : "-")
	}
	if (oc + og >= 5e4) printf "| (the rest) | %.1f | %.1f%% | %.1f | %.1f%% | %.2f |\n", oc / 1e6, 100 * oc / ct,
		og / 1e6, 100 * og / gt, (og > 0 ? oc / og : 0)
	printf "| **total** | **%.1f** | | **%.1f** | | **%.2f** |\n", ct / 1e6, gt / 1e6, ct / gt
}
