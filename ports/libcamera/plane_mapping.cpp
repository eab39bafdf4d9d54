// SPDX-License-Identifier: BSD-2-Clause
#include "plane_mapping.h"

#include <cerrno>
#include <cstring>

#include <sys/mman.h>
#include <unistd.h>

namespace calped {
namespace ports {

BufferMapping &BufferMapping::operator=(BufferMapping &&other) noexcept
{
	if (this == &other)
		return *this;
	unmap();
	for (int i = 0; i < kMaxPlanes; ++i) {
		regions_[i] = other.regions_[i];
		planes_[i] = other.planes_[i];
		other.regions_[i] = Region();
		other.planes_[i] = MappedPlane();
	}
	regionCount_ = other.regionCount_;
	planeCount_ = other.planeCount_;
	other.regionCount_ = 0;
	other.planeCount_ = 0;
	return *this;
}

void BufferMapping::unmap()
{
	for (int i = 0; i < regionCount_; ++i)
		munmap(regions_[i].address, regions_[i].size);
	for (int i = 0; i < kMaxPlanes; ++i) {
		regions_[i] = Region();
		planes_[i] = MappedPlane();
	}
	regionCount_ = 0;
	planeCount_ = 0;
}

namespace {

// Size of the memory behind fd: dmabufs and memfds report it through lseek(SEEK_END),
// which is also what libcamera uses. -1 when the fd cannot tell (then it is not checked).
int64_t memorySize(int fd)
{
	off_t end = lseek(fd, 0, SEEK_END);
	return end < 0 ? -1 : static_cast<int64_t>(end);
}

} // namespace

Status checkPlanes(const PlaneDesc *planes, int count, const int64_t *memorySizes,
		   const char *what)
{
	if (count < 1 || count > BufferMapping::kMaxPlanes)
		return Status::error(ErrorCode::CameraError, "%s has %d planes (calped maps 1 to %d)",
				     what, count, BufferMapping::kMaxPlanes);
	for (int i = 0; i < count; ++i) {
		const PlaneDesc &p = planes[i];
		if (p.fd < 0)
			return Status::error(ErrorCode::CameraError, "%s plane %d has no file descriptor",
					     what, i);
		if (p.length == 0)
			return Status::error(ErrorCode::CameraError, "%s plane %d is empty", what, i);
		if (p.offset > UINT64_MAX - p.length)
			return Status::error(ErrorCode::CameraError,
					     "%s plane %d: offset %llu + length %llu overflows", what, i,
					     static_cast<unsigned long long>(p.offset),
					     static_cast<unsigned long long>(p.length));
		const int64_t size = memorySizes[i];
		if (size >= 0 && p.offset + p.length > static_cast<uint64_t>(size))
			return Status::error(ErrorCode::CameraError,
					     "%s plane %d (offset %llu, length %llu) ends past its memory's %lld bytes",
					     what, i, static_cast<unsigned long long>(p.offset),
					     static_cast<unsigned long long>(p.length),
					     static_cast<long long>(size));
	}
	return Status::success();
}

Status BufferMapping::map(const PlaneDesc *planes, int count, const char *what)
{
	unmap();
	// Validate every plane before mapping anything.
	int64_t sizes[kMaxPlanes];
	for (int i = 0; i < count && i < kMaxPlanes; ++i)
		sizes[i] = planes[i].fd >= 0 ? memorySize(planes[i].fd) : -1;
	const Status checked = checkPlanes(planes, count, sizes, what);
	if (!checked.ok())
		return checked;

	const uint64_t page = static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
	for (int i = 0; i < count; ++i) {
		// Planes sharing an fd were mapped with the first of them.
		bool seen = false;
		for (int j = 0; j < i; ++j)
			seen = seen || planes[j].fd == planes[i].fd;
		if (seen)
			continue;

		uint64_t first = planes[i].offset;
		uint64_t end = planes[i].offset + planes[i].length;
		for (int j = i + 1; j < count; ++j) {
			if (planes[j].fd != planes[i].fd)
				continue;
			first = planes[j].offset < first ? planes[j].offset : first;
			end = planes[j].offset + planes[j].length > end ? planes[j].offset + planes[j].length
									 : end;
		}
		const uint64_t start = first - first % page;
		const size_t size = static_cast<size_t>(end - start);
		void *address = mmap(nullptr, size, PROT_READ, MAP_SHARED, planes[i].fd,
				     static_cast<off_t>(start));
		if (address == MAP_FAILED) {
			int err = errno;
			unmap();
			return Status::error(ErrorCode::CameraError,
					     "%s plane %d: mmap of %zu bytes at offset %llu failed: %s", what,
					     i, size, static_cast<unsigned long long>(start),
					     std::strerror(err));
		}
		regions_[regionCount_++] = Region{ address, size };

		for (int j = i; j < count; ++j) {
			if (planes[j].fd != planes[i].fd)
				continue;
			planes_[j].data = static_cast<const uint8_t *>(address) + (planes[j].offset - start);
			planes_[j].length = static_cast<size_t>(planes[j].length);
		}
	}
	planeCount_ = count;
	return Status::success();
}

} // namespace ports
} // namespace calped
