// SPDX-License-Identifier: BSD-2-Clause
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {

class LdcfFilter;

// One level as the classifier sees it: planes of paddedHeight x paddedWidth cells sharing
// rowStride and planeStride (fixed for the pyramid, so feature offsets are too): the ten
// channels, or LDCF's filtered channels (pyramid/ldcf_filter.h).
struct LevelChannels {
	const uint16_t *data = nullptr;
	int paddedHeight = 0;
	int paddedWidth = 0;
	ptrdiff_t rowStride = 0;
	ptrdiff_t planeStride = 0;
	// Set when the cells are computed as they are read (LdcfFilter::onDemand): read them
	// through onDemand->at(index), not data (which holds only those computed so far).
	LdcfFilter *onDemand = nullptr;
};

} // namespace calped
