// SPDX-License-Identifier: BSD-2-Clause
// stb implementations, compiled only where no stb library provides them (Debian's libstb does).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
