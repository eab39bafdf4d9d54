// SPDX-License-Identifier: BSD-2-Clause
// Full-width bands: which rows each stage must produce for the bands the classifier
// reads, their colour conversion and the computed levels' channels there.
#include "pyramid/pyramid.h"
#include "pyramid/pyramid_util.h"

#include <algorithm>

namespace calped {

using namespace pyramid_util;

void Pyramid::planRows(const CellRange *levelRows, int width, int height)
{
	const int n = scales_.count;
	for (int i = 0; i < n; i++)
		rows_[i] = LevelRows();
	// What the classifier reads, and the raw channel rows the smoothing reaches for;
	// approximated levels pass their needs on to the computed level they resample.
	for (int i = 0; i < n; i++) {
		const PyramidLevel &l = scales_.levels[i];
		LevelRows &r = rows_[i];
		const CellRange wanted = levelRows ? levelRows[i].clipped(l.height) : CellRange{ 0, l.height };
		const CellRange raw = wanted.grown(params_.pyramidSmooth > 0 ? 1 : 0, l.height);
		r.raw.add(raw);
		if (!l.computed && !raw.empty()) {
			// Which source rows the taps read does not depend on their gain.
			const kernels::ResampleTap *taps = levelTaps(i, kTapsY, *scratch_[0]);
			if (taps)
				rows_[l.source].raw.add(sourceRows(taps, raw));
		}
	}
	// The LUV rows each computed level's channels need, with the margin.
	halfLevel_ = halfLevelOf(params_, scales_);
	for (int i = 0; i < n; i++) {
		const PyramidLevel &l = scales_.levels[i];
		if (!l.computed)
			continue;
		LevelRows &r = rows_[i];
		const int s = params_.shrink;
		r.chan = CellRange{ s * r.raw.begin - channelMargin_, s * r.raw.end + channelMargin_ }
				 .clipped(s * l.height);
		if (r.raw.empty())
			r.chan = CellRange();
		r.luv = r.chan;
	}
	// Sources, smallest first: octaves below the half-size image are resampled from it
	// (as the toolbox does), the others from the whole image.
	fullRows_ = CellRange();
	for (int i = n - 1; i >= 0; i--) {
		const PyramidLevel &l = scales_.levels[i];
		const LevelRows &r = rows_[i];
		if (!l.computed || r.luv.empty())
			continue;
		const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
		if (w1 == width && h1 == height) {
			fullRows_.add(r.luv);
			continue;
		}
		const bool fromHalf = halfLevel_ >= 0 && i > halfLevel_;
		const kernels::ResampleTap *taps = levelTaps(i, kTapsY, *scratch_[0]);
		if (!taps)
			continue; // computeBands() reports it
		const CellRange src = sourceRows(taps, r.luv);
		if (fromHalf)
			rows_[halfLevel_].luv.add(src);
		else
			fullRows_.add(src);
	}
	// Colour conversion starts on an even row: 4:2:0 strips start on a chroma row.
	if (!fullRows_.empty())
		fullRows_.begin &= ~1;
}

Status Pyramid::computeBands(FrameInput &input, const CellRange *levelRows)
{
	const auto t0 = StageClock::now();
	const int width = input.width(), height = input.height();
	if (!luv_[0].fits(width, height))
		return Status::error(ErrorCode::ImageTooLarge,
				     "%dx%d is larger than the pyramid was set up for", width, height);
	Status st = scalesFor(width, height, scales_);
	if (!st.ok())
		return st;
	width_ = width;
	height_ = height;
	planRows(levelRows, width, height);
	for (int i = 0; i < scales_.count; i++)
		doneCount_[i] = doneNext_[i] = 0;

	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width, height);
	const Scratch &s = *scratch_[0];
	// Only the rows some level reads.
	const CellRange luvRows = fullRows_;
	fullRows_ = CellRange();
	convertLuvRows(input, luvRows);

	// Computed levels: each keeps its place in the store, so offsets do not depend on
	// which rows a frame needs. Their rows are then computed as parts over the threads
	// (computeTasks), each resampled from the whole image, or from the half-size image
	// below it (as the toolbox does), which is therefore made first.
	size_t offset = 0;
	int tasks = 0;
	computedCount = 0;
	for (int i = 0; i < scales_.count; i++) {
		const PyramidLevel &l = scales_.levels[i];
		const LevelRows &r = rows_[i];
		needCount_[i] = 0;
		if (!l.computed)
			continue;
		const size_t need = size_t(kChannelCount) * l.width * l.height;
		if (offset + need > computedStore_.capacity())
			return Status::error(ErrorCode::ImageTooLarge, "channels of level %d do not fit", i);
		realOffset_[i] = offset;
		offset += need;
		const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
		if (!s.levelLuv[0].fits(w1, h1) || (i == halfLevel_ && !halfLuv_[0].fits(w1, h1)))
			return Status::error(ErrorCode::ImageTooLarge, "level %d does not fit", i);
		if (r.chan.empty()) // a half-size image only the smaller octaves read
			continue;
		needRects_[i][0] = LevelRect{ r.raw, CellRange{ 0, l.width } };
		needCount_[i] = 1;
		tasks_[tasks++] = RectTask{ i, 0, r.raw, long(r.raw.size()) * l.width };
		computedCount++;
	}
	if (halfLevel_ >= 0 && !rows_[halfLevel_].luv.empty()) {
		const Status st = resampleHalf(luv);
		if (!st.ok())
			return st;
	}
	int parts = 0;
	st = computeTasks(input, tasks, parts);
	if (!st.ok())
		return st;
	msChannels = msSince(t0);
	for (auto &each : scratch_)
		each->msApprox = each->msSmooth = each->msFilter = 0;
	return Status::success();
}

Status Pyramid::resampleHalf(const Plane<uint16_t> luv[3])
{
	const int h = halfLevel_;
	const PyramidLevel &l = scales_.levels[h];
	const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
	const kernels::ResampleTap *xTaps = levelTaps(h, kTapsX, *scratch_[0]);
	const kernels::ResampleTap *yTaps = xTaps ? levelTaps(h, kTapsY, *scratch_[0]) : nullptr;
	if (!yTaps)
		return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
	const kernels::ResampleTap *yTapsOf[3] = { yTaps, yTaps, yTaps };
	Plane<uint16_t> half[3];
	for (int c = 0; c < 3; c++)
		half[c] = halfLuv_[c].view(w1, h1);
	// Each output row depends only on its own taps: chunks of rows, each its own.
	const CellRange rows = rows_[h].luv;
	const int chunks = std::min(rows.size(), workers() == 1 ? 1 : 4 * workers());
	auto one = [&](int t, int worker) {
		const CellRange part{ rows.begin + int(long(rows.size()) * t / chunks),
				      rows.begin + int(long(rows.size()) * (t + 1) / chunks) };
		if (!part.empty())
			resampleRows(luv, half, 3, yTapsOf, part, xTaps, *scratch_[size_t(worker)]);
	};
	forEachTask(pool_, chunks, one);
	return Status::success();
}

void Pyramid::convertLuvRows(FrameInput &input, CellRange rows)
{
	rows = rows.clipped(height_);
	if (rows.empty() || fullRows_.contains(rows))
		return;
	// The rows above and below those converted, in chunks of whole strips (the whole
	// part at once when the frame is RGB8 already and there is one thread); chunks start
	// on even rows (4:2:0 chroma). Each chunk writes only its own rows.
	const CellRange parts[2] = { fullRows_.empty() ? rows : CellRange{ rows.begin, fullRows_.begin },
				   fullRows_.empty() ? CellRange() : CellRange{ fullRows_.end, rows.end } };
	const int strip = input.stripRows();
	const int threads = workers();
	int total = 0;
	for (const CellRange &part : parts)
		total += std::max(0, part.size());
	// Several chunks per thread, so that a loaded core does not hold the others up; at
	// most about 120 per part, even (4:2:0) and whole strips.
	int chunk = threads == 1 ? std::max(total, 2) : std::max(16, total / (4 * threads));
	chunk = (std::max(chunk, total / 120 + 2) + 1) & ~1;
	if (strip < chunk)
		chunk = (chunk + strip - 1) / strip * strip;
	CellRange chunks[256];
	int count = 0;
	for (const CellRange &part : parts)
		for (int y0 = part.begin & ~1; !part.empty() && y0 < part.end; y0 += chunk)
			chunks[count++] = CellRange{ y0, std::min(part.end, y0 + chunk) };
	auto one = [&](int t, int worker) {
		Plane<uint16_t> luv[3];
		for (int c = 0; c < 3; c++)
			luv[c] = luv_[c].view(width_, height_);
		uint8_t *scratch = scratch_[size_t(worker)]->strip.data();
		const CellRange &part = chunks[t];
		for (int y0 = part.begin; y0 < part.end; y0 += strip) {
			const int n = std::min(strip, part.end - y0);
			ptrdiff_t stride;
			const uint8_t *rgb = input.rows(y0, n, stride, scratch);
			k_->rgbToLuv(luvTables_, rgb, stride, width_, n, luv[0].row(y0), luv[1].row(y0),
				     luv[2].row(y0), luv[0].stride);
		}
	};
	forEachTask(pool_, count, one);
	fullRows_.add(rows);
}

} // namespace calped
