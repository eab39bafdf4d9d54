// SPDX-License-Identifier: BSD-2-Clause
// calped-convert: Dollár toolbox detector (.mat) -> calped model blob (.cpm).
// Usage and exit codes are in docs/model-format.md.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <system_error>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <calped/model.h>
#include <calped/status.h>

#include "array_dump.h"
#include "atomic_file.h"
#include "detector_clf.h"
#include "detector_filters.h"
#include "detector_opts.h"
#include "mat_reader.h"
#include "program.h"

namespace calped {
namespace convert {

namespace {

constexpr int kExitFailure = 1;

const apps::ProgramInfo kProgram = {
	"calped-convert",
	"usage: calped-convert [--dump-arrays DIR] [--name NAME] IN.mat OUT.cpm\n"
	"\n"
	"Converts a detector trained with Piotr Dollar's toolbox (ACF or LDCF, Matlab v5 .mat)\ninto a "
	"calped model blob (docs/model-format.md).\n"
	"\n"
	"options:\n",
	"\n"
	"exit status: 0 success, 1 conversion error, 2 usage error\n",
};

const std::vector<apps::OptionSpec> kOptions = {
	{ "dump-arrays", "DIR", "also write the raw clf arrays to\n"
				"DIR/{fids,thrs,child,hs,weights,depth}.txt" },
	{ "name", "NAME", "model name stored in the blob (default: IN's file name without .mat)" },
};

struct Options {
	std::string input, output, dumpDir, name;
	bool haveName = false;
};

// Returns -1 when the arguments are fine, else the exit code.
int parseArgs(int argc, char **argv, Options &o)
{
	apps::ParsedArgs args;
	const int rc = apps::parseCommandLine(kProgram, kOptions, true, argc, argv, args);
	if (rc >= 0)
		return rc;
	for (const apps::ParsedOption &opt : args.options) {
		if (opt.name == "name") {
			o.name = opt.value;
			o.haveName = true;
		} else {
			o.dumpDir = opt.value;
		}
	}
	if (args.positional.size() != 2)
		return apps::usageError(kProgram, "expected two arguments, IN.mat and OUT.cpm, got " +
							  std::to_string(args.positional.size()) + " (try --help)");
	o.input = args.positional[0];
	o.output = args.positional[1];
	if (!o.haveName) {
		std::filesystem::path p(o.input);
		o.name = p.extension() == ".mat" ? p.stem().string() : p.filename().string();
	}
	return -1;
}

// libmatio trusts the dimensions written in the file, so one damaged byte can make it try to
// allocate tens of gigabytes. A real detector needs well under 100 MB (the 2.5 MB Caltech
// model peaks at 40 MB), so cap the address space and let those allocations fail instead.
void capAddressSpace(const std::string &input)
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
	(void)input; // sanitizers reserve terabytes of virtual address space
#else
	std::error_code ec;
	const uintmax_t size = std::filesystem::file_size(input, ec);
	if (ec)
		return; // opening it will fail with a proper message
	const rlim_t cap = (static_cast<rlim_t>(512) << 20) + 64 * static_cast<rlim_t>(size);
	struct rlimit limit;
	if (getrlimit(RLIMIT_AS, &limit) != 0)
		return;
	if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > cap) {
		limit.rlim_cur = cap;
		setrlimit(RLIMIT_AS, &limit);
	}
#endif
}

Status writeFile(const std::string &path, const std::vector<uint8_t> &bytes)
{
	// Beside the name, renamed on success: a failure never removes what was at `path`
	// (removing it on a write error once deleted a device node).
	ports::AtomicFile f;
	std::string error;
	if (!f.open(path, error))
		return Status::error(ErrorCode::IoError, "%s", error.c_str());
	std::fwrite(bytes.data(), 1, bytes.size(), f.get());
	if (!f.commit(error))
		return Status::error(ErrorCode::IoError, "%s", error.c_str());
	return Status::success();
}

Status convert(const Options &o, Model &model, size_t &blobSize)
{
	MatFile file;
	MatNode detector, opts, clf;
	Status s = file.open(o.input);
	if (s.ok())
		s = file.read("detector", detector);
	if (s.ok())
		s = field(detector, "opts", opts);
	if (s.ok())
		s = readDetectorOpts(opts, model.params);
	if (s.ok())
		s = readDetectorFilters(opts, model);
	if (s.ok())
		s = field(detector, "clf", clf);
	RawClf raw;
	if (s.ok())
		s = readClf(clf, raw);
	if (s.ok() && !o.dumpDir.empty())
		s = dumpArrays(raw, o.dumpDir);
	if (s.ok())
		s = convertClf(raw, model);
	if (!s.ok())
		return s;
	model.name = o.name;
	s = validateModel(model);
	if (!s.ok())
		return s;
	const std::vector<uint8_t> blob = serializeModel(model);
	if (blob.empty())
		return Status::error(ErrorCode::OutOfMemory, "serialising the model");
	blobSize = blob.size();
	return writeFile(o.output, blob);
}

int run(int argc, char **argv)
{
	Options o;
	const int parsed = parseArgs(argc, argv, o);
	if (parsed >= 0)
		return parsed;
	capAddressSpace(o.input);
	Model model;
	size_t blobSize = 0;
	const Status s = convert(o, model, blobSize);
	if (!s.ok()) {
		std::fprintf(stderr, "calped-convert: %s\n", s.message());
		return kExitFailure;
	}
	const ModelParams &p = model.params;
	char filters[64] = "";
	if (p.nFilters > 0)
		std::snprintf(filters, sizeof(filters), ", %d %dx%d filters per channel", p.nFilters,
			      p.filterSize, p.filterSize);
	std::printf("%s: %d trees x %d nodes, depth %d, window %gx%g in %dx%d, shrink %d, "
		    "stride %d%s -> %s (%zu bytes)\n",
		    model.name.c_str(), model.nTrees, model.nodesPerTree, model.treeDepth,
		    static_cast<double>(p.modelDsH), static_cast<double>(p.modelDsW), p.modelDsPadH,
		    p.modelDsPadW, p.shrink, p.stride, filters, o.output.c_str(), blobSize);
	return 0;
}

} // namespace

} // namespace convert
} // namespace calped

int main(int argc, char **argv)
{
	try {
		return calped::convert::run(argc, argv);
	} catch (const std::bad_alloc &) {
		std::fprintf(stderr, "calped-convert: OutOfMemory: the input needs more memory than allowed\n");
	} catch (const std::exception &e) {
		std::fprintf(stderr, "calped-convert: unexpected failure: %s\n", e.what());
	} catch (...) {
		std::fprintf(stderr, "calped-convert: unexpected failure\n");
	}
	return 1;
}
