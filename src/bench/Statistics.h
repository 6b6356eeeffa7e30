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

// The median of the means of consecutive pairs, (s[i] + s[i+1]) / 2, of samples in the order they
// were taken (one sample: itself; none: 0). The bench keeps two frames in flight (FramePacer), so
// one frame's wall time can move into its neighbour's: on llvmpipe hard on scenes/glass.json ran
// 8-23 and 83-113 ms frames in turn, whose plain median landed on either side of their 50-60 ms
// of GPU time from one round to the next. A pair holds both halves; one slow frame still moves
// only two pairs out of the middle.
double pairedMedian(const std::vector<double>& samples);

// A distribution-free interval for the median of whatever the samples are drawn from: the order
// statistics x(k) and x(n + 1 - k), with k the largest rank at which a Binomial(n, 1/2) count
// leaves at least `coverage` between them (coverage = 1 - 2 P(B <= k - 1); e.g. 12 samples: x(3)
// and x(10), 96.1 %). It assumes only independent samples: the bench's rounds, not the frames of
// one round, which the machine's speed swings tie together. Not found below 6 samples at 95 %.
struct MedianInterval {
    bool found = false;
    double low = 0, high = 0, coverage = 0;
};
MedianInterval medianInterval(std::vector<double> samples, double coverage = 0.95);

// The bench's warm-up ends once the last 6 frame times' pairedMedian is within 5 % of the 6
// before's (pairs, as frames that alternate short and long never settled by the plain median of 5:
// hard on scenes/glass.json ran to the warm-up's cap in 7 of 10 cases at stop 63).
bool framesSettled(const std::vector<double>& frameMs);

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
