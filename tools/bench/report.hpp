// Printing results: a table for people, one JSON object for scripts.
#pragma once

#include <ostream>

#include "tools/bench/options.hpp"
#include "tools/bench/run.hpp"

namespace slmp::bench {

void print_table(std::ostream& out, const Options& options, const Results& results);
void print_json(std::ostream& out, const Options& options, const Results& results);

}  // namespace slmp::bench
