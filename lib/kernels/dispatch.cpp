// SPDX-License-Identifier: BSD-2-Clause
// Kernel tables: the references, and the best available per kernel.
#include "kernels.h"

namespace calped {
namespace kernels {

const KernelTable &referenceKernels()
{
	static const KernelTable table = {
		"ref",
		rgbToLuv_ref,
		resampleRgb8_ref,
		resamplePlane_ref,
		resamplePlanes_ref,
		smoothTri1_ref,
		gradMagOrient_ref,
		triSumR_ref,
		normalizeMag_ref,
		shrink4_ref,
		gradHist4_ref,
		scanDepth2_ref,
		scanTrees_ref,
		scanDepth2List_ref,
		scanTreesList_ref,
		shrink2_ref,
		gradHist2_ref,
		ldcfFilter_ref,
		ldcfCell_ref,
	};
	return table;
}

const KernelTable &portableKernels()
{
	static const KernelTable table = {
		"opt",
		rgbToLuv_ref,
		resampleRgb8_opt,
		resamplePlane_opt,
		resamplePlanes_opt,
		smoothTri1_opt,
		gradMagOrient_opt,
		triSumR_opt,
		normalizeMag_ref,
		shrink4_opt,
		gradHist4_opt,
		scanDepth2_ref,
		scanTrees_ref,
		scanDepth2List_ref,
		scanTreesList_ref,
		shrink2_opt,
		gradHist2_opt,
		ldcfFilter_ref,
		ldcfCell_ref,
	};
	return table;
}

#if CALPED_HAVE_AVX2
namespace {

const KernelTable &avx2Kernels()
{
	static const KernelTable table = [] {
		KernelTable t = portableKernels();
		t.name = "avx2";
		t.rgbToLuv = rgbToLuv_avx2;
		t.gradMagOrient = gradMagOrient_avx2;
		t.smoothTri1 = smoothTri1_avx2;
		t.triSum = triSumR_avx2;
		t.resamplePlane = resamplePlane_avx2;
		t.resamplePlanes = resamplePlanes_avx2;
		t.resampleRgb8 = resampleRgb8_avx2;
		t.normalizeMag = normalizeMag_avx2;
		t.gradHist4 = gradHist4_avx2;
		t.shrink4 = shrink4_avx2;
		t.shrink2 = shrink2_avx2;
		t.gradHist2 = gradHist2_avx2;
		t.scanDepth2 = scanDepth2_avx2;
		t.scanDepth2List = scanDepth2List_avx2;
		t.ldcfFilter = ldcfFilter_avx2;
		t.ldcfCell = ldcfCell_avx2;
		return t;
	}();
	return table;
}

bool cpuHasAvx2()
{
	__builtin_cpu_init();
	return __builtin_cpu_supports("avx2");
}

} // namespace
#endif

// ---- NEON (aarch64, and armv7 built with -mfpu=neon) ------------------------------------
// Chosen at compile time: NEON is part of the base ISA on aarch64, and on armv7 the build
// flags promise it (lib/kernels/meson.build checks that they do).
#if CALPED_HAVE_NEON
namespace {

const KernelTable &neonKernels()
{
	static const KernelTable table = [] {
		KernelTable t = portableKernels();
		t.name = "neon";
		t.rgbToLuv = rgbToLuv_neon;
		t.resampleRgb8 = resampleRgb8_neon;
		t.resamplePlane = resamplePlane_neon;
		t.resamplePlanes = resamplePlanes_neon;
		t.smoothTri1 = smoothTri1_neon;
		t.gradMagOrient = gradMagOrient_neon;
		t.triSum = triSumR_neon;
		t.normalizeMag = normalizeMag_neon;
		t.shrink4 = shrink4_neon;
		t.gradHist4 = gradHist4_neon;
		t.shrink2 = shrink2_neon;
		t.gradHist2 = gradHist2_neon;
		t.scanDepth2List = scanDepth2List_neon; // the grid stays scalar (trees_neon.cpp)
		t.ldcfFilter = ldcfFilter_neon;
		t.ldcfCell = ldcfCell_neon;
		return t;
	}();
	return table;
}

} // namespace
#endif
// ---- end of NEON --------------------------------------------------------------------------

const KernelTable &bestKernels()
{
#if CALPED_HAVE_AVX2
	if (cpuHasAvx2())
		return avx2Kernels();
#endif
#if CALPED_HAVE_NEON
	return neonKernels();
#endif
	return portableKernels();
}

int availableKernelTables(const KernelTable *out[], int capacity)
{
	int n = 0;
	auto add = [&](const KernelTable &t) {
		if (n < capacity)
			out[n++] = &t;
	};
	add(referenceKernels());
	add(portableKernels());
#if CALPED_HAVE_AVX2
	if (cpuHasAvx2())
		add(avx2Kernels());
#endif
#if CALPED_HAVE_NEON
	add(neonKernels());
#endif
	return n;
}


// ==== camera pixel formats -> RGB8 (issue 5) ===========================================
const ConvertKernels &referenceConvertKernels()
{
	static const ConvertKernels table = {
		"ref", bgr8ToRgb8_ref, gray8ToRgb8_ref, yuv420ToRgb8_ref, yuyvToRgb8_ref, bayerToRgb8_ref,
	};
	return table;
}

namespace {

// Optimised versions only where callgrind showed they pay (docs/pixel-formats.md).
const ConvertKernels &portableConvertKernels()
{
	static const ConvertKernels table = {
		"opt", bgr8ToRgb8_ref, gray8ToRgb8_ref, yuv420ToRgb8_opt, yuyvToRgb8_opt, bayerToRgb8_opt,
	};
	return table;
}

#if CALPED_HAVE_AVX2
const ConvertKernels &avx2ConvertKernels()
{
	static const ConvertKernels table = {
		"avx2", bgr8ToRgb8_avx2, gray8ToRgb8_avx2, yuv420ToRgb8_avx2, yuyvToRgb8_avx2, bayerToRgb8_avx2,
	};
	return table;
}
#endif

#if CALPED_HAVE_NEON
const ConvertKernels &neonConvertKernels()
{
	static const ConvertKernels table = {
		"neon", bgr8ToRgb8_neon, gray8ToRgb8_neon, yuv420ToRgb8_neon, yuyvToRgb8_neon, bayerToRgb8_neon,
	};
	return table;
}
#endif

} // namespace

const ConvertKernels &bestConvertKernels()
{
#if CALPED_HAVE_AVX2
	if (cpuHasAvx2())
		return avx2ConvertKernels();
#endif
#if CALPED_HAVE_NEON
	return neonConvertKernels();
#endif
	return portableConvertKernels();
}

int availableConvertKernels(const ConvertKernels *out[], int capacity)
{
	int n = 0;
	auto add = [&](const ConvertKernels &t) {
		if (n < capacity)
			out[n++] = &t;
	};
	add(referenceConvertKernels());
	add(portableConvertKernels());
#if CALPED_HAVE_AVX2
	if (cpuHasAvx2())
		add(avx2ConvertKernels());
#endif
#if CALPED_HAVE_NEON
	add(neonConvertKernels());
#endif
	return n;
}
// ==== end of camera pixel formats ========================================================

} // namespace kernels
} // namespace calped
