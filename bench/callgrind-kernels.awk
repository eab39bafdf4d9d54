# SPDX-License-Identifier: BSD-2-Clause
# callgrind_annotate's self cost per function -> "kernel <tab> instructions" lines and
# "total <tab> N" (bench/kernel-shares.sh; run with -f bench/kernel-name.awk).
/PROGRAM TOTALS/ { gsub(",", "", $1); print "total\t" $1; next }
/^ *[0-9,]+ +\(/ && /:/ {
	n = $1; gsub(",", "", n)
	f = $0; sub(/^[^:]*:/, "", f)
	sum[kernelOf(f)] += n
}
END { for (k in sum) print k "\t" sum[k] }
