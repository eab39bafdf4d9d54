// SPDX-License-Identifier: BSD-2-Clause
#include "array_dump.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace calped {
namespace convert {

namespace {

int formatValue(char *buf, size_t size, double v, NumberClass cls)
{
	switch (cls) {
	case NumberClass::Integer:
		return std::snprintf(buf, size, "%lld", static_cast<long long>(v));
	case NumberClass::Single:
		return std::snprintf(buf, size, "%.9g", static_cast<double>(static_cast<float>(v)));
	case NumberClass::Double:
		break;
	}
	return std::snprintf(buf, size, "%.17g", v);
}

Status writeArray(const RawArray &a, const std::string &path)
{
	std::FILE *f = std::fopen(path.c_str(), "w");
	if (!f)
		return Status::error(ErrorCode::IoError, "cannot create %s: %s", path.c_str(),
				     std::strerror(errno));
	char buf[64];
	// Column-major storage: element (row, col) is at row + rows * col.
	for (size_t row = 0; row < a.rows; row++) {
		for (size_t col = 0; col < a.cols; col++) {
			if (col)
				std::fputc(' ', f);
			formatValue(buf, sizeof(buf), a.values[row + a.rows * col], a.cls);
			std::fputs(buf, f);
		}
		std::fputc('\n', f);
	}
	const bool failed = std::ferror(f) != 0;
	if (std::fclose(f) != 0 || failed)
		return Status::error(ErrorCode::IoError, "cannot write %s", path.c_str());
	return Status::success();
}

} // namespace

Status dumpArrays(const RawClf &clf, const std::string &dir)
{
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec)
		return Status::error(ErrorCode::IoError, "cannot create directory %s: %s", dir.c_str(),
				     ec.message().c_str());
	const RawArray *arrays[RawClf::kCount];
	clf.list(arrays);
	for (const RawArray *a : arrays) {
		Status s = writeArray(*a, (std::filesystem::path(dir) / (a->name + ".txt")).string());
		if (!s.ok())
			return s;
	}
	return Status::success();
}

} // namespace convert
} // namespace calped
