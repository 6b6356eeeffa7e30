#pragma once
// Order statistics of a set of samples (frame times, pass times).
#include <vector>

namespace penumbra::bench {

struct Summary {
    int count = 0;
    double min = 0, max = 0, mean = 0, median = 0, p95 = 0;
};

// Empty input gives an all-zero summary. Percentiles by nearest rank.
Summary summarize(std::vector<double> samples);

}  // namespace penumbra::bench
