// SPDX-License-Identifier: BSD-2-Clause
// Ground truth of one sequence and its two readers: CVML XML (PETS 2009 as annotated by
// Milan et al., frame numbers 0-based) and MOTChallenge gt.txt (frames 1-based).
// Both produce 1-based frame numbers, the harness's numbering (frame k = k-th image).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "boxes.h"

namespace calped::eval_tool {

class GroundTruth
{
public:
	void add(long frame, const GtBox &box);
	// Boxes of a 1-based frame (empty for frames the file does not mention).
	const std::vector<GtBox> &boxes(long frame) const;
	// Largest frame number holding a box, 0 if none.
	long lastFrame() const { return frames_.empty() ? 0 : frames_.rbegin()->first; }
	// Boxes in frames 1..upTo, counted (ignore == false) or ignored.
	long count(long upTo, bool ignore) const;

private:
	// Sparse: memory follows the boxes, not the largest frame number a file states.
	std::map<long, std::vector<GtBox>> frames_;
};

// Chooses the reader by content: a file starting with '<' is CVML XML, anything else is
// read as MOTChallenge text. Errors name the file and, for malformed content, the line.
bool loadGroundTruth(const std::string &path, GroundTruth &out, std::string &error);

// CVML: <frame number="k"> (0-based) <objectlist> <object id> <box h w xc yc/>; boxes are
// given by centre and size. Needs expat; without it this fails with an explanation.
bool readCvmlGroundTruth(const std::string &path, GroundTruth &out, std::string &error);

// MOTChallenge: frame,id,x,y,w,h[,flag[,class[,visibility]]]; flag 0 marks an ignore box.
bool readMotGroundTruth(const std::string &path, GroundTruth &out, std::string &error);

// The same readers on text already in memory (the fuzz targets use these); `name` stands
// for the file in error messages.
bool parseGroundTruth(const char *data, size_t size, const std::string &name, GroundTruth &out,
		      std::string &error);
bool parseCvmlGroundTruth(const char *data, size_t size, const std::string &name,
			  GroundTruth &out, std::string &error);
bool parseMotGroundTruth(const char *data, size_t size, const std::string &name,
			 GroundTruth &out, std::string &error);

// True when this build can read CVML XML.
bool cvmlSupported();

} // namespace calped::eval_tool
