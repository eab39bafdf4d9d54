// SPDX-License-Identifier: BSD-2-Clause
// serializeModel: Model -> blob (docs/model-format.md). It does not validate, so tests can
// build blobs with a correct checksum around out-of-range content.
#include <calped/model.h>

#include <algorithm>
#include <new>

#include "core/crc32.h"
#include "model/blob_format.h"
#include "model/byte_io.h"

namespace calped {

namespace {

void writeParams(ByteWriter &w, const ModelParams &p)
{
	// Declaration order of ModelParams; offsets in docs/model-format.md.
	w.f32(p.modelDsH);
	w.f32(p.modelDsW);
	w.i32(p.modelDsPadH);
	w.i32(p.modelDsPadW);
	w.i32(p.stride);
	w.f32(p.cascThr);
	w.i32(p.shrink);
	w.i32(p.colorSmooth);
	w.i32(p.gradNormRad);
	w.f32(p.gradNormConst);
	w.i32(p.gradColorChn);
	w.i32(p.gradFull);
	w.i32(p.histBinSize);
	w.i32(p.nOrients);
	w.i32(p.softBin);
	w.i32(p.nPerOct);
	w.i32(p.nOctUp);
	w.i32(p.nApprox);
	for (float lambda : p.lambdas)
		w.f32(lambda);
	w.i32(p.padH);
	w.i32(p.padW);
	w.f32(p.minDsH);
	w.f32(p.minDsW);
	w.i32(p.pyramidSmooth);
	w.f32(p.nmsOverlap);
	w.u32(static_cast<uint32_t>(p.nmsOverlapDenominator));
	w.i32(p.nFilters);
	w.i32(p.filterSize);
}

} // namespace

std::vector<uint8_t> serializeModel(const Model &model)
{
	// Only refuse what the layout cannot express: array lengths are implied by the shape.
	if (model.nTrees < 0 || model.nodesPerTree < 0 || model.name.size() > UINT32_MAX)
		return {};
	const size_t n = static_cast<size_t>(model.nTrees) * static_cast<size_t>(model.nodesPerTree);
	if (model.fids.size() != n || model.thrs.size() != n || model.child.size() != n ||
	    model.hs.size() != n)
		return {};
	const ModelParams &p = model.params;
	if (p.nFilters < 0 || p.filterSize < 0 ||
	    model.filters.size() != size_t(p.nFilters) * 10 * size_t(p.filterSize) * size_t(p.filterSize))
		return {};

	try {
		std::vector<uint8_t> blob;
		blob.reserve(blob::kHeaderSize + blob::kFixedPayloadSize + model.name.size() +
			     4 * model.filters.size() + n * blob::kBytesPerNode);
		blob.resize(blob::kHeaderSize); // filled in once the payload is known

		ByteWriter w(blob);
		writeParams(w, model.params);
		w.i32(model.nTrees);
		w.i32(model.nodesPerTree);
		w.i32(model.treeDepth);
		w.u32(static_cast<uint32_t>(model.name.size()));
		w.bytes(model.name.data(), model.name.size());
		for (int32_t v : model.filters)
			w.i32(v);
		for (uint32_t v : model.fids)
			w.u32(v);
		for (int32_t v : model.thrs)
			w.i32(v);
		for (uint32_t v : model.child)
			w.u32(v);
		for (int32_t v : model.hs)
			w.i32(v);

		const size_t payloadSize = blob.size() - blob::kHeaderSize;
		const uint8_t *payload = blob.data() + blob::kHeaderSize;
		std::vector<uint8_t> header;
		ByteWriter h(header);
		h.bytes(blob::kMagic, sizeof(blob::kMagic));
		h.u32(blob::kVersion);
		h.u32(static_cast<uint32_t>(blob::kHeaderSize));
		h.u64(payloadSize);
		h.u32(crc32(payload, payloadSize));
		h.u32(crc32(header.data(), blob::kHeaderCrcOffset));
		std::copy(header.begin(), header.end(), blob.begin());
		return blob;
	} catch (const std::bad_alloc &) {
		return {};
	}
}

} // namespace calped
