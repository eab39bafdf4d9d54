// SPDX-License-Identifier: BSD-2-Clause
// The `calped` element: an in-place video filter that runs calped's pedestrian detector on
// every frame and attaches one GstVideoRegionOfInterestMeta per detection (docs/gstreamer.md).
#pragma once

#include <gst/gst.h>
#include <gst/video/gstvideofilter.h>

G_BEGIN_DECLS

#define GST_TYPE_CALPED (gst_calped_get_type())
G_DECLARE_FINAL_TYPE(GstCalped, gst_calped, GST, CALPED, GstVideoFilter)

GST_ELEMENT_REGISTER_DECLARE(calped);

G_END_DECLS
