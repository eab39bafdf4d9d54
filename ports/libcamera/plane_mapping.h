// SPDX-License-Identifier: BSD-2-Clause
// Maps the planes of one frame buffer into memory, once, at setup. libcamera describes a
// buffer as planes (fd, offset, length); several planes often share one dmabuf (NV12 in a
// single V4L2 buffer: Y at offset 0, UV after it). Each distinct fd is mapped once, from
// the page holding its first plane to the end of its last, read-only.
// Independent of libcamera, so it is tested on memfds.
#pragma once

#include <cstddef>
#include <cstdint>

#include <calped/status.h>

namespace calped {
namespace ports {

struct PlaneDesc {
	int fd = -1;
	uint64_t offset = 0;
	uint64_t length = 0;
};

struct MappedPlane {
	const uint8_t *data = nullptr;
	size_t length = 0;
};

// Checks a buffer's plane descriptions before anything is mapped (pure: fuzzed by
// tests/fuzz/fuzz_libcamera.cpp). `memorySizes[i]` is the size of plane i's memory (its
// fd's), or -1 when the fd cannot tell. Errors (CameraError, naming `what` and the plane):
// no planes or more than BufferMapping::kMaxPlanes, an invalid fd, an empty plane, offset +
// length overflowing, a plane reaching past the end of its memory.
Status checkPlanes(const PlaneDesc *planes, int count, const int64_t *memorySizes,
		   const char *what);

class BufferMapping
{
public:
	static constexpr int kMaxPlanes = 4;

	BufferMapping() = default;
	~BufferMapping() { unmap(); }
	BufferMapping(BufferMapping &&other) noexcept { *this = static_cast<BufferMapping &&>(other); }
	BufferMapping &operator=(BufferMapping &&other) noexcept;
	BufferMapping(const BufferMapping &) = delete;
	BufferMapping &operator=(const BufferMapping &) = delete;

	// Maps `count` planes. Errors (CameraError, naming `what` and the plane): no planes or
	// more than kMaxPlanes, an invalid fd, an empty plane, a plane reaching past the end of
	// its fd's memory (when the fd reports its size), mmap failure. On error nothing stays
	// mapped.
	Status map(const PlaneDesc *planes, int count, const char *what);
	void unmap();

	int planeCount() const { return planeCount_; }
	const MappedPlane &plane(int i) const { return planes_[i]; }
	const MappedPlane *planes() const { return planes_; }
	// Distinct mmap calls made (one per distinct fd).
	int regionCount() const { return regionCount_; }

private:
	struct Region {
		void *address = nullptr;
		size_t size = 0;
	};
	Region regions_[kMaxPlanes];
	int regionCount_ = 0;
	MappedPlane planes_[kMaxPlanes];
	int planeCount_ = 0;
};

} // namespace ports
} // namespace calped
