// SPDX-License-Identifier: BSD-2-Clause
// Umbrella header of the calped core library.
#pragma once

#include <calped/auto_resize.h>
#include <calped/calibration.h>
#include <calped/self_calibrating_detector.h>
#include <calped/self_calibration.h>
#include <calped/detector.h>
#include <calped/image.h>
#include <calped/model.h>
#include <calped/status.h>
#include <calped/version.h>
