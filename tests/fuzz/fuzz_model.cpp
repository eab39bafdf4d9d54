// SPDX-License-Identifier: BSD-2-Clause
// loadModel on arbitrary bytes, three times: as a whole blob (header, magic, version, CRCs),
// and as a payload wrapped in a version-2 and in a version-1 header with correct CRCs, so
// mutations reach the payload parser (version 2's filter shape and weights included) and
// validateModel instead of stopping at the checksum. A model that loads must validate
// and survive serializeModel -> loadModel unchanged.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <calped/model.h>

#include "core/crc32.h"
#include "model/blob_format.h"
#include "model/byte_io.h"

#include "fuzz_checks.h"

using namespace calped;

namespace {

std::vector<uint8_t> wrapPayload(const uint8_t *payload, size_t size, uint32_t version)
{
	std::vector<uint8_t> blob(blob::kHeaderSize);
	for (size_t i = 0; i < sizeof(blob::kMagic); i++)
		blob[i] = blob::kMagic[i];
	writeLe32(&blob[blob::kVersionOffset], version);
	writeLe32(&blob[blob::kHeaderSizeOffset], blob::kHeaderSize);
	writeLe32(&blob[blob::kPayloadSizeOffset], static_cast<uint32_t>(size));
	writeLe32(&blob[blob::kPayloadSizeOffset + 4], static_cast<uint32_t>(uint64_t(size) >> 32));
	blob.insert(blob.end(), payload, payload + size);
	writeLe32(&blob[blob::kPayloadCrcOffset], crc32(blob.data() + blob::kHeaderSize, size));
	writeLe32(&blob[blob::kHeaderCrcOffset], crc32(blob.data(), blob::kHeaderCrcOffset));
	return blob;
}

bool sameModel(const Model &a, const Model &b)
{
	return a.name == b.name && a.nTrees == b.nTrees && a.nodesPerTree == b.nodesPerTree &&
	       a.treeDepth == b.treeDepth && a.fids == b.fids && a.thrs == b.thrs &&
	       a.child == b.child && a.hs == b.hs && a.featureCount() == b.featureCount() &&
	       a.params.nFilters == b.params.nFilters && a.params.filterSize == b.params.filterSize &&
	       a.filters == b.filters;
}

void check(const uint8_t *data, size_t size)
{
	Model m;
	const Status st = loadModel(data, size, m);
	if (!st.ok()) {
		// A failed load leaves the model empty and says why on one printable line.
		if (m.nTrees != 0 || !m.fids.empty())
			fuzz::fail("a failed load leaves the model empty", st.message());
		if (!fuzz::printableLine(st.message()))
			fuzz::fail("the message is one printable line", st.message());
		return;
	}
	if (!validateModel(m).ok())
		fuzz::fail("a loaded model validates", validateModel(m).message());
	const std::vector<uint8_t> again = serializeModel(m);
	Model m2;
	if (!loadModel(again.data(), again.size(), m2).ok() || !sameModel(m, m2))
		fuzz::fail("a loaded model survives serializeModel and loadModel", "");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	check(data, size);
	for (uint32_t version : { blob::kVersion, blob::kOldestVersion }) {
		const std::vector<uint8_t> wrapped = wrapPayload(data, size, version);
		check(wrapped.data(), wrapped.size());
	}
	return 0;
}
