// What the prism-bench subcommands that time other programs share (povray, mpi):
// running a shell command and keeping its output, quoting for the shell, and
// the median of repeated timings.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

std::string shellQuote(const std::string& s);
// Runs `command` and returns its standard output and error together; `status`
// is pclose's.
std::string capture(const std::string& command, int* status);
// The median of `v` (0 when empty).
double median(std::vector<double> v);

}  // namespace prism::bench
