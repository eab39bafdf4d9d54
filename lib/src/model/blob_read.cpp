// SPDX-License-Identifier: BSD-2-Clause
// loadModel: blob -> Model. Header and checksums first, then a bounds-checked parse of the
// payload, then validateModel. `out` only receives a model that passed everything.
#include <calped/model.h>

#include <cstring>
#include <new>

#include "core/crc32.h"
#include "model/blob_format.h"
#include "model/byte_io.h"

namespace calped {

namespace {

Status checkHeader(const uint8_t *data, size_t size, size_t &payloadSize, uint32_t &versionOut)
{
	if (size == 0)
		return Status::error(ErrorCode::ModelTruncated, "the input is empty");
	const size_t magicBytes = size < sizeof(blob::kMagic) ? size : sizeof(blob::kMagic);
	if (std::memcmp(data, blob::kMagic, magicBytes) != 0)
		return Status::error(ErrorCode::ModelBadMagic,
				     "not a calped model (starts with %02X %02X %02X %02X, expected \"CALPEDM\")",
				     data[0], size > 1 ? data[1] : 0, size > 2 ? data[2] : 0,
				     size > 3 ? data[3] : 0);
	if (size < blob::kHeaderSizeOffset)
		return Status::error(ErrorCode::ModelTruncated,
				     "%zu bytes, shorter than the %zu-byte header", size, blob::kHeaderSize);
	// The version is read before anything else so a newer blob is reported as such.
	const uint32_t version = readLe32(data + blob::kVersionOffset);
	if (version < blob::kOldestVersion || version > blob::kVersion)
		return Status::error(ErrorCode::ModelBadVersion,
				     "version = %u, this library reads versions %u to %u", version,
				     blob::kOldestVersion, blob::kVersion);
	versionOut = version;
	if (size < blob::kHeaderSize)
		return Status::error(ErrorCode::ModelTruncated,
				     "%zu bytes, shorter than the %zu-byte header", size, blob::kHeaderSize);
	const uint32_t headerCrc = readLe32(data + blob::kHeaderCrcOffset);
	const uint32_t actualHeaderCrc = crc32(data, blob::kHeaderCrcOffset);
	if (headerCrc != actualHeaderCrc)
		return Status::error(ErrorCode::ModelChecksum,
				     "header CRC-32 is 0x%08X but the header says 0x%08X",
				     actualHeaderCrc, headerCrc);
	const uint32_t headerSize = readLe32(data + blob::kHeaderSizeOffset);
	if (headerSize != blob::kHeaderSize)
		return Status::error(ErrorCode::ModelInvalid, "headerSize = %u, versions 1 and 2 require %zu",
				     headerSize, blob::kHeaderSize);
	const uint64_t declared = readLe64(data + blob::kPayloadSizeOffset);
	const size_t present = size - blob::kHeaderSize;
	if (declared > present)
		return Status::error(ErrorCode::ModelTruncated,
				     "payloadSize = %llu but only %zu bytes follow the header",
				     static_cast<unsigned long long>(declared), present);
	if (declared < present)
		return Status::error(ErrorCode::ModelInvalid,
				     "%zu trailing bytes after the %llu-byte payload",
				     present - static_cast<size_t>(declared),
				     static_cast<unsigned long long>(declared));
	payloadSize = static_cast<size_t>(declared);
	const uint32_t payloadCrc = readLe32(data + blob::kPayloadCrcOffset);
	const uint32_t actualPayloadCrc = crc32(data + blob::kHeaderSize, payloadSize);
	if (payloadCrc != actualPayloadCrc)
		return Status::error(ErrorCode::ModelChecksum,
				     "payload CRC-32 is 0x%08X but the header says 0x%08X",
				     actualPayloadCrc, payloadCrc);
	return Status::success();
}

bool readParams(ByteReader &r, uint32_t version, ModelParams &p)
{
	uint32_t dnm = 0;
	const bool ok = r.f32(p.modelDsH) && r.f32(p.modelDsW) && r.i32(p.modelDsPadH) &&
			r.i32(p.modelDsPadW) && r.i32(p.stride) && r.f32(p.cascThr) &&
			r.i32(p.shrink) && r.i32(p.colorSmooth) && r.i32(p.gradNormRad) &&
			r.f32(p.gradNormConst) && r.i32(p.gradColorChn) && r.i32(p.gradFull) &&
			r.i32(p.histBinSize) && r.i32(p.nOrients) && r.i32(p.softBin) &&
			r.i32(p.nPerOct) && r.i32(p.nOctUp) && r.i32(p.nApprox) &&
			r.f32(p.lambdas[0]) && r.f32(p.lambdas[1]) && r.f32(p.lambdas[2]) &&
			r.i32(p.padH) && r.i32(p.padW) && r.f32(p.minDsH) && r.f32(p.minDsW) &&
			r.i32(p.pyramidSmooth) && r.f32(p.nmsOverlap) && r.u32(dnm);
	// Out-of-range values survive the cast and are reported by validateModel.
	p.nmsOverlapDenominator = static_cast<NmsOverlapDenominator>(dnm);
	// Version 1 predates LDCF: no filters.
	p.nFilters = 0;
	p.filterSize = 0;
	if (version >= 2)
		return ok && r.i32(p.nFilters) && r.i32(p.filterSize);
	return ok;
}

template <typename T, typename Read>
void readArray(ByteReader &r, size_t n, std::vector<T> &out, Read read)
{
	out.resize(n);
	for (size_t i = 0; i < n; i++)
		(r.*read)(out[i]); // cannot fail: the caller checked the remaining length
}

Status parsePayload(const uint8_t *payload, size_t size, uint32_t version, Model &m)
{
	ByteReader r(payload, size);
	uint32_t nameLength = 0;
	if (!readParams(r, version, m.params) || !r.i32(m.nTrees) || !r.i32(m.nodesPerTree) ||
	    !r.i32(m.treeDepth) || !r.u32(nameLength))
		return Status::error(ErrorCode::ModelInvalid,
				     "payload is %zu bytes, shorter than its %zu fixed bytes", size,
				     version >= 2 ? blob::kFixedPayloadSize : blob::kFixedPayloadSizeV1);
	if (nameLength > blob::kMaxNameLength)
		return Status::error(ErrorCode::ModelInvalid, "name length = %u exceeds %u bytes",
				     nameLength, blob::kMaxNameLength);
	const uint8_t *name = r.take(nameLength);
	if (!name)
		return Status::error(ErrorCode::ModelInvalid,
				     "name length = %u runs past the end of the payload", nameLength);
	m.name.assign(reinterpret_cast<const char *>(name), nameLength);
	// Check the shape before sizing any array, so a bad count cannot trigger a huge allocation.
	if (m.nTrees < 1 || m.nTrees > blob::kMaxTrees)
		return Status::error(ErrorCode::ModelInvalid, "nTrees = %d must be in [1, %d]",
				     m.nTrees, blob::kMaxTrees);
	if (m.nodesPerTree < 1 || m.nodesPerTree > blob::kMaxNodesPerTree)
		return Status::error(ErrorCode::ModelInvalid, "nodesPerTree = %d must be in [1, %d]",
				     m.nodesPerTree, blob::kMaxNodesPerTree);
	// The filter shape is checked before its array is sized, as the tree shape below.
	const ModelParams &p = m.params;
	if (p.nFilters < 0 || p.nFilters > blob::kMaxFilters)
		return Status::error(ErrorCode::ModelInvalid, "nFilters = %d must be in [0, %d]",
				     p.nFilters, blob::kMaxFilters);
	if (p.filterSize < 0 || p.filterSize > blob::kMaxFilterSize)
		return Status::error(ErrorCode::ModelInvalid, "filterSize = %d must be in [0, %d]",
				     p.filterSize, blob::kMaxFilterSize);
	const size_t f = size_t(p.nFilters) * 10 * size_t(p.filterSize) * size_t(p.filterSize);
	if (r.remaining() < f * 4)
		return Status::error(ErrorCode::ModelInvalid,
				     "filter weights (nFilters %d x 10 x %d x %d) run past the end of the payload",
				     p.nFilters, p.filterSize, p.filterSize);
	readArray(r, f, m.filters, &ByteReader::i32);
	const size_t n = static_cast<size_t>(m.nTrees) * static_cast<size_t>(m.nodesPerTree);
	if (r.remaining() != n * blob::kBytesPerNode)
		return Status::error(ErrorCode::ModelInvalid,
				     "node arrays are %zu bytes, nTrees %d x nodesPerTree %d needs %zu",
				     r.remaining(), m.nTrees, m.nodesPerTree, n * blob::kBytesPerNode);
	readArray(r, n, m.fids, &ByteReader::u32);
	readArray(r, n, m.thrs, &ByteReader::i32);
	readArray(r, n, m.child, &ByteReader::u32);
	readArray(r, n, m.hs, &ByteReader::i32);
	return Status::success();
}

} // namespace

Status loadModel(const uint8_t *data, size_t size, Model &out)
{
	out = Model();
	if (!data && size > 0)
		return Status::error(ErrorCode::InvalidArgument, "data is null but size is %zu", size);
	size_t payloadSize = 0;
	uint32_t version = 0;
	Status s = checkHeader(data, size, payloadSize, version);
	if (!s.ok())
		return s;
	try {
		Model m;
		s = parsePayload(data + blob::kHeaderSize, payloadSize, version, m);
		if (s.ok())
			s = validateModel(m);
		if (s.ok())
			out = std::move(m);
		return s;
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%zu-byte model blob", size);
	}
}

} // namespace calped
