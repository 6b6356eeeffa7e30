#pragma once
// Order statistics of a set of samples (frame times, pass times), and least-squares lines through
// paired ones (pass time against triangles drawn).
#include <cstddef>
#include <vector>

namespace penumbra::bench {

struct Summary {
    int count = 0;
    double min = 0, max = 0, mean = 0, median = 0, p95 = 0;
};

// Empty input gives an all-zero summary. Percentiles by nearest rank.
Summary summarize(std::vector<double> samples);

// y ≈ intercept + slope·x by ordinary least squares, with the coefficient of determination
// R² = 1 − Σ(y − ŷ)² / Σ(y − ȳ)²: the share of y's variance the line explains.
struct LineFit {
    std::size_t count = 0;
    double slope = 0, intercept = 0, r2 = 0;
};
// Fewer than two distinct x give slope 0 through the mean and R² 0; y all equal (and fitted
// exactly) give R² 1. x and y must have the same length (throws std::invalid_argument).
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace penumbra::bench
