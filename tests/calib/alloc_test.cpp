// SPDX-License-Identifier: BSD-2-Clause
// The geometry and distortion functions must not allocate (the detector calls them per
// frame): counts every global operator new while they run. Its own binary, since it
// replaces operator new.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace {
std::atomic<long> gAllocations{ 0 };
}

void *operator new(std::size_t size)
{
	gAllocations++;
	if (void *p = std::malloc(size ? size : 1))
		return p;
	throw std::bad_alloc();
}

void operator delete(void *p) noexcept
{
	std::free(p);
}

void operator delete(void *p, std::size_t) noexcept
{
	std::free(p);
}

namespace calped {
namespace {

double exercise(const CameraModel &m, const std::vector<PointCorrespondence> &pts,
		long &allocations)
{
	const long before = gAllocations;
	double sum = 0;
	for (double v = 0; v < 720; v += 7)
		for (double u = 0; u < 1280; u += 11) {
			const Eigen::Vector2d p(u, v);
			Eigen::Vector2d g;
			if (m.pixelToGround(p, g))
				sum += g.sum();
			sum += m.boxWorldHeight(p, Eigen::Vector2d(u, v - 80));
			sum += m.boxPixelHeight(p, 1.8);
			sum += m.undistort(p).sum() + m.distort(p).sum();
			sum += m.worldToPixel(Eigen::Vector3d(u / 100, v / 10, 1)).sum();
			sum += m.horizonRow(u) + m.depth(Eigen::Vector3d(1, 2, 3));
		}
	DltResult r;
	if (estimateProjectionDlt(pts.data(), pts.size(), r).ok())
		sum += r.rmsError;
	allocations = gAllocations - before;
	return sum;
}

TEST(Allocation, GeometryAndDltDoNotAllocate)
{
	std::vector<PointCorrespondence> pts;
	const CameraModel pitched = calib_test::pitchedCamera();
	for (double z : { 0.0, 1.0, 2.0 })
		for (double x = -5; x <= 5; x += 5) {
			PointCorrespondence p;
			p.world = Eigen::Vector3d(x, 10 + 3 * z + x, z);
			p.image = pitched.project(p.world);
			pts.push_back(p);
		}
	for (const char *file : { "pitched_tsai_kappa.xml", "pitched_distorted.ci",
				  "pitched_P_mm.txt" }) {
		const CameraModel m = calib_test::loadData(file);
		ASSERT_TRUE(m.valid()) << file;
		long allocations = -1;
		const double sum = exercise(m, pts, allocations);
		EXPECT_EQ(allocations, 0) << file << " (checksum " << sum << ")";
	}
}

} // namespace
} // namespace calped
