// SPDX-License-Identifier: BSD-2-Clause
#include "detect/world_coordinates.h"

namespace calped {

void addWorldCoordinates(const CameraModel &camera, Detection *boxes, int count)
{
	for (int i = 0; i < count; i++) {
		Detection &d = boxes[i];
		const Eigen::Vector2d foot(d.x + d.w / 2.0, d.y + double(d.h)), head(d.x + d.w / 2.0, d.y);
		Eigen::Vector2d ground;
		if (camera.pixelToGround(foot, ground)) {
			d.groundX = float(ground.x());
			d.groundY = float(ground.y());
		}
		d.worldHeight = float(camera.boxWorldHeight(foot, head));
	}
}

} // namespace calped
