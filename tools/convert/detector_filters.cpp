// SPDX-License-Identifier: BSD-2-Clause
#include "detector_filters.h"

#include <cmath>
#include <vector>

#include "model/blob_format.h"
#include "model/fixed_convert.h"

namespace calped {
namespace convert {

Status readDetectorFilters(const MatNode &opts, Model &model)
{
	ModelParams &p = model.params;
	p.nFilters = 0;
	p.filterSize = 0;
	model.filters.clear();
	if (!hasField(opts, "filters"))
		return Status::success();
	MatNode node;
	Status s = field(opts, "filters", node);
	if (!s.ok() || elementCount(node) == 0)
		return s;
	std::vector<size_t> dims = dimensions(node);
	if (dims.size() == 3)
		dims.push_back(1);
	const bool shapeOk = dims.size() == 4 && dims[0] == dims[1] && dims[0] % 2 == 1 &&
			     dims[0] <= size_t(blob::kMaxFilterSize) && dims[2] == 10 && dims[3] >= 1 &&
			     dims[3] <= size_t(blob::kMaxFilters);
	if (!shapeOk)
		return Status::error(ErrorCode::ModelInvalid,
				     "%s is %s, expected k x k x 10 x n filters (k odd, at most %d; n at most %d)",
				     node.path.c_str(), shapeString(node).c_str(), blob::kMaxFilterSize,
				     blob::kMaxFilters);
	std::vector<double> values;
	s = numbers(node, values);
	if (!s.ok())
		return s;
	const size_t k = dims[0], n = dims[3];
	std::vector<int32_t> weights(values.size());
	// Matlab order: index y + k * (x + k * (c + 10 * j)); calped's: x + k * (y + k * (c + 10 * j)).
	for (size_t j = 0; j < n; j++)
		for (size_t c = 0; c < 10; c++)
			for (size_t x = 0; x < k; x++)
				for (size_t y = 0; y < k; y++) {
					const size_t plane = c + 10 * j;
					const double v = values[y + k * (x + k * plane)];
					if (!(std::isfinite(v) && std::fabs(v) <= 1.0))
						return Status::error(ErrorCode::ModelInvalid,
								     "%s(%zu, %zu, %zu, %zu) = %g is not in [-1, 1]",
								     node.path.c_str(), y + 1, x + 1, c + 1, j + 1, v);
					weights[x + k * (y + k * plane)] = filterWeightToFixed(v);
				}
	p.nFilters = static_cast<int32_t>(n);
	p.filterSize = static_cast<int32_t>(k);
	model.filters = std::move(weights);
	return Status::success();
}

} // namespace convert
} // namespace calped
