// SPDX-License-Identifier: BSD-2-Clause
// Running the optional external programs (ffmpeg, ffprobe, gnuplot) through the shell.
#pragma once

#include <string>

namespace calped::eval_tool {

// 'text' quoted for /bin/sh.
std::string shellQuote(const std::string &text);

// True if `name` is an executable file in a folder of $PATH.
bool findExecutable(const std::string &name);

// Runs `command` with /bin/sh, capturing its standard output. Fails, with the exit status in
// `error`, unless the command exits 0.
bool runCapture(const std::string &command, std::string &output, std::string &error);

// Describes a pclose()/system() status: "exit status 1", "signal 9".
std::string describeExitStatus(int status);

} // namespace calped::eval_tool
