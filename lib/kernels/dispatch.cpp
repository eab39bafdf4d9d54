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
		smoothTri1_ref,
		gradMagOrient_ref,
		triSumR_ref,
		normalizeMag_ref,
		shrink4_ref,
		gradHist4_ref,
		scanDepth2_ref,
		scanTrees_ref,
	};
	return table;
}

const KernelTable &bestKernels()
{
	static const KernelTable table = {
		"opt",
		rgbToLuv_ref,
		resampleRgb8_ref,
		resamplePlane_opt,
		smoothTri1_opt,
		gradMagOrient_opt,
		triSumR_opt,
		normalizeMag_ref,
		shrink4_ref,
		gradHist4_ref,
		scanDepth2_ref,
		scanTrees_ref,
	};
	return table;
}

} // namespace kernels
} // namespace calped
