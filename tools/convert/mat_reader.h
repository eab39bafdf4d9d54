// SPDX-License-Identifier: BSD-2-Clause
// A thin, checked view of a MAT file read with libmatio: open a file, walk struct fields by
// name and read numbers or text, with every failure a Status naming the field's full path.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <calped/status.h>

struct _mat_t;
struct matvar_t;

namespace calped {
namespace convert {

// How a numeric array was stored, so --dump-arrays can print it as read.
enum class NumberClass { Integer, Single, Double };

// A variable or struct field and its path from the file's root, e.g. "detector.opts.stride".
struct MatNode {
	matvar_t *var = nullptr;
	std::string path;
};

// Owns an open MAT file and the one top-level variable read from it.
class MatFile
{
public:
	MatFile() = default;
	MatFile(const MatFile &) = delete;
	MatFile &operator=(const MatFile &) = delete;
	~MatFile();

	Status open(const std::string &path);
	// Reads a top-level variable (the file keeps ownership).
	Status read(const char *name, MatNode &out);

private:
	_mat_t *file_ = nullptr;
	matvar_t *var_ = nullptr;
	std::string path_;
};

// Number of elements (product of the dimensions).
size_t elementCount(const MatNode &node);
// Rows and columns of a two-dimensional array; false for any other rank.
bool matrixShape(const MatNode &node, size_t &rows, size_t &cols);
// Every dimension, in order (empty for a missing variable).
std::vector<size_t> dimensions(const MatNode &node);
// "7x2048": the dimensions, for messages.
std::string shapeString(const MatNode &node);

bool hasField(const MatNode &parent, const char *name);
// Fails unless parent is a 1x1 struct with that field.
Status field(const MatNode &parent, const char *name, MatNode &out);

// Every element of a real numeric (or logical) array, converted to double (exact for all
// classes the toolbox uses), in the file's column-major order.
Status numbers(const MatNode &node, std::vector<double> &out, NumberClass *cls = nullptr);
// A char array as text (non-ASCII characters become '?').
Status text(const MatNode &node, std::string &out);

} // namespace convert
} // namespace calped
