// SPDX-License-Identifier: BSD-2-Clause
// Buffer plane mapping on memfds and a temporary file: several planes sharing one fd at
// unaligned offsets, planes on different fds, bad descriptions, and no mapping left behind.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include "plane_mapping.h"

namespace calped {
namespace ports {
namespace {

// A memfd of `size` bytes where byte i is (i * 7 + i / 251) & 0xff: every offset has a
// value that tells where it came from.
class MemFd
{
public:
	MemFd(const char *name, size_t size)
	{
		fd_ = memfd_create(name, MFD_CLOEXEC);
		if (fd_ < 0)
			return;
		std::vector<uint8_t> bytes(size);
		for (size_t i = 0; i < size; ++i)
			bytes[i] = pattern(i);
		if (write(fd_, bytes.data(), size) != static_cast<ssize_t>(size)) {
			close(fd_);
			fd_ = -1;
		}
	}
	~MemFd()
	{
		if (fd_ >= 0)
			close(fd_);
	}
	int fd() const { return fd_; }
	static uint8_t pattern(size_t i) { return static_cast<uint8_t>(i * 7 + i / 251); }

private:
	int fd_ = -1;
};

// Mappings in this process whose name contains `name` (/proc/self/maps lines).
int mappingsNamed(const std::string &name)
{
	std::ifstream maps("/proc/self/maps");
	std::string line;
	int n = 0;
	while (std::getline(maps, line))
		n += line.find(name) != std::string::npos;
	return n;
}

void expectPlaneHolds(const MappedPlane &plane, uint64_t offset, uint64_t length)
{
	ASSERT_NE(plane.data, nullptr);
	ASSERT_EQ(plane.length, length);
	for (uint64_t i = 0; i < length; i += 97)
		ASSERT_EQ(plane.data[i], MemFd::pattern(offset + i)) << "byte " << i;
	ASSERT_EQ(plane.data[length - 1], MemFd::pattern(offset + length - 1));
}

TEST(LibcameraPlaneMapping, ThreePlanesShareOneFdAtUnalignedOffsets)
{
	// YUV420 640x481 with stride 640 in one buffer: Y, U, V back to back. The U and V
	// offsets are not page multiples.
	const uint64_t y = 640 * 481, c = 320 * 241;
	MemFd mem("calped-planes-shared", y + 2 * c + 100);
	ASSERT_GE(mem.fd(), 0);
	PlaneDesc planes[3] = { { mem.fd(), 0, y }, { mem.fd(), y, c }, { mem.fd(), y + c, c } };
	ASSERT_NE(y % 4096, 0u);

	BufferMapping m;
	Status st = m.map(planes, 3, "test buffer");
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(m.planeCount(), 3);
	EXPECT_EQ(m.regionCount(), 1); // one mmap for the shared fd
	expectPlaneHolds(m.plane(0), 0, y);
	expectPlaneHolds(m.plane(1), y, c);
	expectPlaneHolds(m.plane(2), y + c, c);
	EXPECT_EQ(m.plane(1).data, m.plane(0).data + y);
}

TEST(LibcameraPlaneMapping, FirstPlaneAtUnalignedOffsetInsideLaterPage)
{
	MemFd mem("calped-planes-offset", 3 * 4096);
	ASSERT_GE(mem.fd(), 0);
	PlaneDesc planes[2] = { { mem.fd(), 5000, 1000 }, { mem.fd(), 9000, 2000 } };
	BufferMapping m;
	Status st = m.map(planes, 2, "test buffer");
	ASSERT_TRUE(st.ok()) << st.message();
	expectPlaneHolds(m.plane(0), 5000, 1000);
	expectPlaneHolds(m.plane(1), 9000, 2000);
}

TEST(LibcameraPlaneMapping, PlanesOnDifferentFdsAreMappedSeparately)
{
	MemFd luma("calped-planes-luma", 64 * 48), chroma("calped-planes-chroma", 64 * 24 + 10);
	ASSERT_GE(luma.fd(), 0);
	ASSERT_GE(chroma.fd(), 0);
	PlaneDesc planes[2] = { { luma.fd(), 0, 64 * 48 }, { chroma.fd(), 10, 64 * 24 } };
	BufferMapping m;
	Status st = m.map(planes, 2, "test buffer");
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(m.regionCount(), 2);
	expectPlaneHolds(m.plane(0), 0, 64 * 48);
	expectPlaneHolds(m.plane(1), 10, 64 * 24);
}

TEST(LibcameraPlaneMapping, RegularTemporaryFileWorksToo)
{
	char path[] = "/tmp/calped-plane-XXXXXX";
	int fd = mkstemp(path);
	ASSERT_GE(fd, 0);
	unlink(path);
	std::vector<uint8_t> bytes(10000);
	for (size_t i = 0; i < bytes.size(); ++i)
		bytes[i] = MemFd::pattern(i);
	ASSERT_EQ(write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
	PlaneDesc planes[2] = { { fd, 0, 6000 }, { fd, 6000, 4000 } };
	{
		BufferMapping m;
		Status st = m.map(planes, 2, "file buffer");
		ASSERT_TRUE(st.ok()) << st.message();
		expectPlaneHolds(m.plane(1), 6000, 4000);
	}
	close(fd);
}

TEST(LibcameraPlaneMapping, PlanePastTheEndIsRefusedNamingIt)
{
	MemFd mem("calped-planes-short", 8192);
	ASSERT_GE(mem.fd(), 0);
	PlaneDesc planes[2] = { { mem.fd(), 0, 4096 }, { mem.fd(), 4096, 4097 } };
	BufferMapping m;
	Status st = m.map(planes, 2, "camera 'x' buffer 3");
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "camera 'x' buffer 3 plane 1"), nullptr) << st.message();
	EXPECT_NE(std::strstr(st.message(), "8192"), nullptr) << st.message();
	EXPECT_EQ(m.planeCount(), 0);
	EXPECT_EQ(m.regionCount(), 0);
}

TEST(LibcameraPlaneMapping, BadDescriptionsAreRefused)
{
	MemFd mem("calped-planes-bad", 4096);
	ASSERT_GE(mem.fd(), 0);
	BufferMapping m;
	PlaneDesc noFd[1] = { { -1, 0, 100 } };
	EXPECT_EQ(m.map(noFd, 1, "b").code(), ErrorCode::CameraError);
	PlaneDesc empty[1] = { { mem.fd(), 0, 0 } };
	EXPECT_EQ(m.map(empty, 1, "b").code(), ErrorCode::CameraError);
	PlaneDesc overflow[1] = { { mem.fd(), UINT64_MAX - 10, 100 } };
	EXPECT_EQ(m.map(overflow, 1, "b").code(), ErrorCode::CameraError);
	PlaneDesc five[5] = {};
	for (PlaneDesc &p : five)
		p = PlaneDesc{ mem.fd(), 0, 16 };
	EXPECT_EQ(m.map(five, 5, "b").code(), ErrorCode::CameraError);
	EXPECT_EQ(m.map(five, 0, "b").code(), ErrorCode::CameraError);
	EXPECT_EQ(m.planeCount(), 0);
}

TEST(LibcameraPlaneMapping, UnmapAndDestructionLeaveNoMapping)
{
	MemFd a("calped-planes-leak", 3 * 4096), b("calped-planes-leak", 4096);
	ASSERT_GE(a.fd(), 0);
	const std::string name = "calped-planes-leak";
	const int before = mappingsNamed(name);
	PlaneDesc planes[3] = { { a.fd(), 0, 4096 }, { a.fd(), 4096, 8192 }, { b.fd(), 0, 4096 } };
	{
		BufferMapping m;
		ASSERT_TRUE(m.map(planes, 3, "b").ok());
		EXPECT_EQ(mappingsNamed(name), before + 2);
		m.unmap();
		EXPECT_EQ(mappingsNamed(name), before);
		ASSERT_TRUE(m.map(planes, 3, "b").ok());
		// Moving hands the mapping over; only one owner unmaps it.
		BufferMapping moved(std::move(m));
		EXPECT_EQ(m.planeCount(), 0);
		EXPECT_EQ(moved.planeCount(), 3);
		EXPECT_EQ(mappingsNamed(name), before + 2);
	}
	EXPECT_EQ(mappingsNamed(name), before);
	// A failed map() after a good one drops the old mapping too.
	BufferMapping m;
	ASSERT_TRUE(m.map(planes, 3, "b").ok());
	PlaneDesc bad[1] = { { a.fd(), 0, 1 << 20 } };
	EXPECT_FALSE(m.map(bad, 1, "b").ok());
	EXPECT_EQ(mappingsNamed(name), before);
}

} // namespace
} // namespace ports
} // namespace calped
