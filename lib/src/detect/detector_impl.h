// SPDX-License-Identifier: BSD-2-Clause
#pragma once
#include <calped/detector.h>
namespace calped {
class DetectorImpl
{
public:
	DetectorConfig config;
	FrameStats stats;
};
} // namespace calped
