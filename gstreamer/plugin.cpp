// SPDX-License-Identifier: BSD-2-Clause
// The gstcalped plugin: the `calped` element (docs/gstreamer.md).
#include <gst/gst.h>

#include "gstcalped.h"

static gboolean plugin_init(GstPlugin *plugin)
{
	return GST_ELEMENT_REGISTER(calped, plugin);
}

GST_PLUGIN_DEFINE(GST_VERSION_MAJOR, GST_VERSION_MINOR, calped,
		  "calped pedestrian detector (ACF, calibrated cameras)", plugin_init, CALPED_GST_VERSION,
		  "BSD", "calped", "calped")
