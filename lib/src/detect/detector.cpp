// SPDX-License-Identifier: BSD-2-Clause
// TEMPORARY placeholder so tools link while the real detector is written.
#include <calped/detector.h>
#include "detect/detector_impl.h"
namespace calped {
Status Detector::create(const Model &, const DetectorConfig &config, std::unique_ptr<Detector> &out)
{
	out.reset(new Detector());
	out->impl_.reset(new DetectorImpl());
	out->impl_->config = config;
	return Status::success();
}
Detector::~Detector() = default;
Status Detector::detect(const ImageView &, Detections &out)
{
	out = Detections();
	return Status::success();
}
const FrameStats &Detector::lastStats() const { return impl_->stats; }
const DetectorConfig &Detector::config() const { return impl_->config; }
} // namespace calped
