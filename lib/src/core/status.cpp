// SPDX-License-Identifier: BSD-2-Clause
#include <calped/status.h>

#include <cstdio>
#include <cstring>

namespace calped {

const char *errorCodeName(ErrorCode code)
{
	switch (code) {
	case ErrorCode::Ok: return "Ok";
	case ErrorCode::InvalidArgument: return "InvalidArgument";
	case ErrorCode::UnsupportedPixelFormat: return "UnsupportedPixelFormat";
	case ErrorCode::ImageEmpty: return "ImageEmpty";
	case ErrorCode::ImageTooLarge: return "ImageTooLarge";
	case ErrorCode::ImageTooSmall: return "ImageTooSmall";
	case ErrorCode::ModelTruncated: return "ModelTruncated";
	case ErrorCode::ModelBadMagic: return "ModelBadMagic";
	case ErrorCode::ModelBadVersion: return "ModelBadVersion";
	case ErrorCode::ModelChecksum: return "ModelChecksum";
	case ErrorCode::ModelInvalid: return "ModelInvalid";
	case ErrorCode::ModelUnsupported: return "ModelUnsupported";
	case ErrorCode::OutOfMemory: return "OutOfMemory";
	case ErrorCode::IoError: return "IoError";
	case ErrorCode::ParseError: return "ParseError";
	case ErrorCode::CameraNotFound: return "CameraNotFound";
	case ErrorCode::CameraError: return "CameraError";
	case ErrorCode::CameraLost: return "CameraLost";
	case ErrorCode::Timeout: return "Timeout";
	case ErrorCode::EndOfStream: return "EndOfStream";
	}
	return "Unknown";
}

Status Status::error(ErrorCode code, const char *fmt, ...)
{
	Status s;
	s.code_ = code;
	int n = std::snprintf(s.message_, sizeof(s.message_), "%s: ", errorCodeName(code));
	if (n < 0 || n >= static_cast<int>(sizeof(s.message_)))
		return s;
	va_list args;
	va_start(args, fmt);
	std::vsnprintf(s.message_ + n, sizeof(s.message_) - n, fmt, args);
	va_end(args);
	return s;
}

} // namespace calped
