// SPDX-License-Identifier: BSD-2-Clause
#include "mat_reader.h"

#include "capped_file.h"
#include "mat_integrity.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>

#include <matio.h>

namespace calped {
namespace convert {

namespace {

// matio reports problems through a log callback; its default one prints several lines and
// aborts on errors. Keep the last message for our one-line error instead.
std::string &lastMatioMessage()
{
	static std::string message;
	return message;
}

void matioLog(int level, char *message)
{
	std::string &last = lastMatioMessage();
	last = message ? message : "";
	for (char &c : last)
		if (c == '\n' || c == '\r')
			c = ' '; // the tool reports errors on one line
	if (level & MATIO_LOG_LEVEL_ERROR) {
		// matio does not expect to continue after an error-level report.
		std::fprintf(stderr, "calped-convert: ParseError: libmatio: %s\n",
			     lastMatioMessage().c_str());
		std::exit(1);
	}
}

std::string matioDetail()
{
	const std::string &m = lastMatioMessage();
	return m.empty() ? std::string() : " (libmatio: " + m + ")";
}

template <typename T>
void appendAll(const void *data, size_t n, std::vector<double> &out)
{
	const T *p = static_cast<const T *>(data);
	for (size_t i = 0; i < n; i++)
		out.push_back(static_cast<double>(p[i]));
}

} // namespace

MatFile::~MatFile()
{
	if (var_)
		Mat_VarFree(var_);
	if (file_)
		Mat_Close(file_);
}

Status MatFile::open(const std::string &path)
{
	Mat_LogInitFunc("calped-convert", matioLog);
	path_ = path;
	// A regular file only (a FIFO would block, a device never end), of a bounded size;
	// then fopen: matio does not say why a file could not be opened.
	struct stat info;
	if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode))
		return Status::error(ErrorCode::IoError, "cannot read %s: not a regular file (a FIFO or device)",
				     path.c_str());
	constexpr long long kMaxMatBytes = 256ll << 20; // the toolbox's models are 0.1-3 MB
	if (::stat(path.c_str(), &info) == 0 && info.st_size > kMaxMatBytes)
		return Status::error(ErrorCode::IoError, "cannot read %s: %lld bytes, over the %lld-byte limit for a MAT file",
				     path.c_str(), static_cast<long long>(info.st_size), kMaxMatBytes);
	std::FILE *f = std::fopen(path.c_str(), "rb");
	if (!f)
		return Status::error(ErrorCode::IoError, "cannot open %s: %s", path.c_str(),
				     std::strerror(errno));
	const bool empty = std::fgetc(f) == EOF;
	const int readError = std::ferror(f) ? errno : 0; // e.g. a directory
	std::fclose(f);
	if (readError)
		return Status::error(ErrorCode::IoError, "cannot read %s: %s", path.c_str(),
				     std::strerror(readError));
	if (empty)
		return Status::error(ErrorCode::ParseError, "%s is empty, not a MAT file", path.c_str());
	// What matio does not check: elements that tile the file, compressed ones complete
	// with their checksum (a truncated or changed file is refused, never converted).
	std::vector<uint8_t> bytes;
	std::string error;
	if (!files::readFileBytes(path, bytes, error, "", size_t(kMaxMatBytes)))
		return Status::error(ErrorCode::IoError, "%s", error.c_str());
	if (!checkMatIntegrity(bytes.data(), bytes.size(), error))
		return Status::error(ErrorCode::ParseError, "%s: %s", path.c_str(), error.c_str());
	lastMatioMessage().clear();
	file_ = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
	if (!file_)
		return Status::error(ErrorCode::ParseError, "%s is not a MAT file (Matlab v5)%s",
				     path.c_str(), matioDetail().c_str());
	return Status::success();
}

Status MatFile::read(const char *name, MatNode &out)
{
	if (var_) {
		Mat_VarFree(var_);
		var_ = nullptr;
	}
	lastMatioMessage().clear();
	var_ = Mat_VarRead(file_, name);
	if (!var_)
		return Status::error(ErrorCode::ModelInvalid, "%s has no variable '%s'%s",
				     path_.c_str(), name, matioDetail().c_str());
	out.var = var_;
	out.path = name;
	return Status::success();
}

size_t elementCount(const MatNode &node)
{
	if (!node.var || node.var->rank <= 0 || !node.var->dims)
		return 0;
	size_t n = 1;
	for (int i = 0; i < node.var->rank; i++)
		n *= node.var->dims[i];
	return n;
}

bool matrixShape(const MatNode &node, size_t &rows, size_t &cols)
{
	if (!node.var || node.var->rank != 2 || !node.var->dims)
		return false;
	rows = node.var->dims[0];
	cols = node.var->dims[1];
	return true;
}

std::vector<size_t> dimensions(const MatNode &node)
{
	std::vector<size_t> dims;
	if (!node.var || node.var->rank <= 0 || !node.var->dims)
		return dims;
	for (int i = 0; i < node.var->rank; i++)
		dims.push_back(node.var->dims[i]);
	return dims;
}

std::string shapeString(const MatNode &node)
{
	if (!node.var || node.var->rank <= 0 || !node.var->dims)
		return "0x0";
	std::string s;
	for (int i = 0; i < node.var->rank; i++) {
		if (i)
			s += 'x';
		s += std::to_string(node.var->dims[i]);
	}
	return s;
}

namespace {

// Looks a field up without Mat_VarGetStructFieldByName, which trusts the struct's field
// table and crashes on some damaged files; here every pointer and size is checked first.
matvar_t *findField(const MatNode &parent, const char *name)
{
	matvar_t *v = parent.var;
	if (!v || v->class_type != MAT_C_STRUCT || elementCount(parent) != 1)
		return nullptr;
	const unsigned count = Mat_VarGetNumberOfFields(v);
	char *const *names = Mat_VarGetStructFieldnames(v);
	if (count == 0 || !names || !v->data || v->nbytes < count * sizeof(matvar_t *))
		return nullptr;
	matvar_t *const *fields = static_cast<matvar_t *const *>(v->data);
	for (unsigned i = 0; i < count; i++)
		if (names[i] && std::strcmp(names[i], name) == 0)
			return fields[i];
	return nullptr;
}

} // namespace

bool hasField(const MatNode &parent, const char *name)
{
	return findField(parent, name) != nullptr;
}

Status field(const MatNode &parent, const char *name, MatNode &out)
{
	if (!parent.var || parent.var->class_type != MAT_C_STRUCT || elementCount(parent) != 1)
		return Status::error(ErrorCode::ModelInvalid, "%s is not a 1x1 struct",
				     parent.path.c_str());
	matvar_t *v = findField(parent, name);
	if (!v)
		return Status::error(ErrorCode::ModelInvalid, "%s.%s is missing", parent.path.c_str(),
				     name);
	out.var = v;
	out.path = parent.path + "." + name;
	return Status::success();
}

Status numbers(const MatNode &node, std::vector<double> &out, NumberClass *cls)
{
	out.clear();
	const matvar_t *v = node.var;
	if (!v)
		return Status::error(ErrorCode::ModelInvalid, "%s is missing", node.path.c_str());
	if (v->isComplex)
		return Status::error(ErrorCode::ModelInvalid, "%s is complex, expected real numbers",
				     node.path.c_str());
	size_t size = 0;
	NumberClass kind = NumberClass::Integer;
	switch (v->class_type) {
	case MAT_C_DOUBLE: size = 8; kind = NumberClass::Double; break;
	case MAT_C_SINGLE: size = 4; kind = NumberClass::Single; break;
	case MAT_C_INT8: case MAT_C_UINT8: size = 1; break;
	case MAT_C_INT16: case MAT_C_UINT16: size = 2; break;
	case MAT_C_INT32: case MAT_C_UINT32: size = 4; break;
	case MAT_C_INT64: case MAT_C_UINT64: size = 8; break;
	default:
		return Status::error(ErrorCode::ModelInvalid, "%s is not a numeric array (matio class %d)",
				     node.path.c_str(), static_cast<int>(v->class_type));
	}
	const size_t n = elementCount(node);
	if (n == 0)
		return Status::success();
	if (!v->data || v->nbytes < n * size || static_cast<size_t>(v->data_size) != size)
		return Status::error(ErrorCode::ModelInvalid, "%s: %zu elements but %zu data bytes",
				     node.path.c_str(), n, v->nbytes);
	out.reserve(n);
	switch (v->class_type) {
	case MAT_C_DOUBLE: appendAll<double>(v->data, n, out); break;
	case MAT_C_SINGLE: appendAll<float>(v->data, n, out); break;
	case MAT_C_INT8: appendAll<int8_t>(v->data, n, out); break;
	case MAT_C_UINT8: appendAll<uint8_t>(v->data, n, out); break;
	case MAT_C_INT16: appendAll<int16_t>(v->data, n, out); break;
	case MAT_C_UINT16: appendAll<uint16_t>(v->data, n, out); break;
	case MAT_C_INT32: appendAll<int32_t>(v->data, n, out); break;
	case MAT_C_UINT32: appendAll<uint32_t>(v->data, n, out); break;
	case MAT_C_INT64: appendAll<int64_t>(v->data, n, out); break;
	case MAT_C_UINT64: appendAll<uint64_t>(v->data, n, out); break;
	default: break;
	}
	if (cls)
		*cls = kind;
	return Status::success();
}

Status text(const MatNode &node, std::string &out)
{
	out.clear();
	const matvar_t *v = node.var;
	if (!v || v->class_type != MAT_C_CHAR)
		return Status::error(ErrorCode::ModelInvalid, "%s is not text", node.path.c_str());
	const size_t n = elementCount(node);
	if (n == 0)
		return Status::success();
	const size_t unit = v->data_size == 2 ? 2 : 1; // UTF-16 / UINT16 or 8-bit storage
	if (!v->data || v->nbytes < n * unit)
		return Status::error(ErrorCode::ModelInvalid, "%s: %zu characters but %zu data bytes",
				     node.path.c_str(), n, v->nbytes);
	const uint8_t *p = static_cast<const uint8_t *>(v->data);
	for (size_t i = 0; i < n; i++) {
		unsigned c = p[i];
		if (unit == 2) {
			uint16_t wide; // matio keeps 16-bit characters in host byte order
			std::memcpy(&wide, p + 2 * i, sizeof(wide));
			c = wide;
		}
		out += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
	}
	return Status::success();
}

} // namespace convert
} // namespace calped
