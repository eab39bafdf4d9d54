// SPDX-License-Identifier: BSD-2-Clause
// Error reporting for the whole public API: functions return a Status, they never throw.
#pragma once

#include <cstdarg>

namespace calped {

// Every failure a caller can cause has its own code (documented in docs/errors.md).
enum class ErrorCode {
	Ok = 0,
	InvalidArgument,        // a parameter is out of its documented range
	UnsupportedPixelFormat, // the image's pixel format is not handled
	ImageEmpty,             // width or height is 0, or the data pointer is null
	ImageTooLarge,          // larger than the maximum frame size fixed at setup
	ImageTooSmall,          // smaller than the model window after resizing
	ModelTruncated,         // blob shorter than its header or declared size
	ModelBadMagic,          // not a calped model blob
	ModelBadVersion,        // a blob version this library does not read
	ModelChecksum,          // payload CRC-32 does not match
	ModelInvalid,           // a field is out of range (names the field)
	ModelUnsupported,       // a valid model using an option calped does not implement
	OutOfMemory,            // setup could not allocate its buffers
	IoError,                // a file could not be read or written (tools and ports)
	ParseError,             // a text input is malformed (names file and line)
	CameraNotFound,         // ports: no camera matches the id, or none exists
	CameraError,            // ports: the camera refused a setting or failed to start
	CameraLost,             // ports: the camera stopped answering or disappeared mid-stream
	Timeout,                // ports: no frame arrived within the timeout
	EndOfStream,            // ports: a finite source (file sequence) has no more frames
};

// Name of an error code, e.g. "ModelChecksum".
const char *errorCodeName(ErrorCode code);

// Result of an operation: a code and a human-readable message. Fixed size, so reporting
// an error never allocates (the per-frame path may fail without touching the heap).
class Status
{
public:
	Status() = default;
	static Status success() { return Status(); }
	static Status error(ErrorCode code, const char *fmt, ...)
#if defined(__GNUC__)
		__attribute__((format(printf, 2, 3)))
#endif
		;

	bool ok() const { return code_ == ErrorCode::Ok; }
	ErrorCode code() const { return code_; }
	// "ModelChecksum: payload CRC-32 is 0x1234 but the header says 0x5678"
	const char *message() const { return message_; }

private:
	ErrorCode code_ = ErrorCode::Ok;
	char message_[256] = "ok";
};

} // namespace calped
