// SPDX-License-Identifier: BSD-2-Clause
#include "calib_test_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "calib/xml_reader.h"

namespace calped::calib_test {

bool readFile(const std::string &path, std::string &out)
{
	std::ifstream f(path, std::ios::binary);
	if (!f)
		return false;
	std::stringstream s;
	s << f.rdbuf();
	out = s.str();
	return !f.bad();
}

std::string dataPath(const std::string &name)
{
	const char *src = std::getenv("CALPED_SOURCE_DIR");
	const std::string root = src && *src ? src : ".";
	return root + "/tests/calib/data/" + name;
}

std::string sharedPath(const std::string &relative)
{
	const char *env = std::getenv("CALPED_SHARED_DIR");
	const std::string dir = env && *env ? env : "../shared";
	struct stat st;
	if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
		return "";
	const std::string path = dir + "/" + relative;
	if (stat(path.c_str(), &st) != 0)
		return "";
	return path;
}

Status loadText(const std::string &text, CameraModel &out)
{
	return loadCalibration(text.data(), text.size(), "<test>", out);
}

CameraModel loadData(const std::string &name)
{
	CameraModel m;
	std::string text;
	const std::string path = dataPath(name);
	if (!readFile(path, text)) {
		ADD_FAILURE() << "cannot read " << path;
		return m;
	}
	Status st = loadCalibration(text.data(), text.size(), name.c_str(), m);
	EXPECT_TRUE(st.ok()) << st.message();
	return m;
}

CameraModel levelCamera()
{
	Eigen::Matrix3d K;
	K << 1000, 0, 640, 0, 1000, 360, 0, 0, 1;
	Eigen::Matrix3d R; // camera x = world x, camera y (down) = -world z, optical axis = +y
	R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	const Eigen::Vector3d t(0, 5, 0); // -R C with C = (0, 0, 5)
	CameraModel m;
	Status st = CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, m);
	EXPECT_TRUE(st.ok()) << st.message();
	return m;
}

Eigen::Matrix3d pitchedK()
{
	Eigen::Matrix3d K;
	K << 1000, 0, 640, 0, 1000, 360, 0, 0, 1;
	return K;
}

Eigen::Matrix3d pitchedR()
{
	const double s = 0.5, c = std::sqrt(3.0) / 2;
	Eigen::Matrix3d R; // rows: camera x, y (image down), z (optical axis) in world
	R << 1, 0, 0, 0, -s, -c, 0, c, -s;
	return R;
}

Eigen::Vector3d pitchedT()
{
	return -pitchedR() * Eigen::Vector3d(0, 0, 10);
}

CameraModel pitchedCamera()
{
	CameraModel m;
	Status st = CameraModel::fromPinhole(pitchedK(), pitchedR(), pitchedT(), LengthUnit::Metre, m);
	EXPECT_TRUE(st.ok()) << st.message();
	return m;
}

bool readCvml(const std::string &path, std::vector<GtBox> &out, std::string &error)
{
	std::string text;
	if (!readFile(path, text)) {
		error = "cannot read " + path;
		return false;
	}
	std::vector<calib::XmlElement> elements;
	Status st = calib::parseXml(text.data(), text.size(), path.c_str(), elements);
	if (!st.ok()) {
		error = st.message();
		return false;
	}
	out.clear();
	for (const calib::XmlElement &e : elements) {
		if (e.name != "box")
			continue;
		// box -> object -> objectlist -> frame
		int frameIndex = e.parent;
		for (int up = 0; up < 2 && frameIndex >= 0; up++)
			frameIndex = elements[frameIndex].parent;
		const calib::XmlAttribute *number =
			frameIndex >= 0 ? elements[frameIndex].attribute("number") : nullptr;
		const calib::XmlAttribute *h = e.attribute("h"), *w = e.attribute("w");
		const calib::XmlAttribute *xc = e.attribute("xc"), *yc = e.attribute("yc");
		if (!number || !h || !w || !xc || !yc) {
			error = path + ": box on line " + std::to_string(e.line) + " is incomplete";
			return false;
		}
		GtBox b;
		b.frame = std::atoi(number->value.c_str());
		b.h = std::atof(h->value.c_str());
		b.w = std::atof(w->value.c_str());
		b.xc = std::atof(xc->value.c_str());
		b.yc = std::atof(yc->value.c_str());
		out.push_back(b);
	}
	return true;
}

std::string edit(const std::string &text, const std::string &from, const std::string &to)
{
	const size_t at = text.find(from);
	if (at == std::string::npos) {
		ADD_FAILURE() << "'" << from << "' not in the test input";
		return text;
	}
	std::string out = text;
	out.replace(at, from.size(), to);
	return out;
}

std::string dropLines(const std::string &text, const std::string &what)
{
	std::string out;
	size_t pos = 0;
	bool dropped = false;
	while (pos < text.size()) {
		size_t eol = text.find('\n', pos);
		eol = eol == std::string::npos ? text.size() : eol + 1;
		const std::string line = text.substr(pos, eol - pos);
		if (line.find(what) == std::string::npos)
			out += line;
		else
			dropped = true;
		pos = eol;
	}
	if (!dropped)
		ADD_FAILURE() << "no line contains '" << what << "'";
	return out;
}

void expectErrors(Loader load, const std::vector<BadInput> &cases)
{
	std::set<std::string> seen;
	for (const BadInput &c : cases) {
		CameraModel m;
		const Status st = load(c.text.data(), c.text.size(), "bad.file", m);
		const std::string msg = st.message();
		EXPECT_EQ(st.code(), c.code) << c.label << ": " << msg;
		EXPECT_NE(msg.find(c.expected), std::string::npos)
			<< c.label << ": expected '" << c.expected << "' in: " << msg;
		EXPECT_NE(msg.find("bad.file"), std::string::npos) << c.label << ": " << msg;
		EXPECT_FALSE(m.valid()) << c.label;
		EXPECT_TRUE(seen.insert(msg).second) << c.label << ": same message as another case: "
						      << msg;
		std::printf("    %-28s %s\n", c.label, msg.c_str());
	}
}

Summary summarise(std::vector<double> values)
{
	Summary s;
	if (values.empty())
		return s;
	std::sort(values.begin(), values.end());
	s.min = values.front();
	s.max = values.back();
	const size_t n = values.size();
	s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
	return s;
}

} // namespace calped::calib_test
