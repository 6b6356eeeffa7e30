#include "bench/Statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace penumbra::bench {

static double nearestRank(const std::vector<double>& sorted, double p) {
    const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

Summary summarize(std::vector<double> samples) {
    Summary s;
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    s.count = static_cast<int>(samples.size());
    s.min = samples.front();
    s.max = samples.back();
    s.mean = std::accumulate(samples.begin(), samples.end(), 0.0) / static_cast<double>(samples.size());
    const std::size_t n = samples.size();
    s.median = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    s.p95 = nearestRank(samples, 0.95);
    return s;
}

double pairedMedian(const std::vector<double>& samples) {
    if (samples.size() < 2) return samples.empty() ? 0.0 : samples.front();
    std::vector<double> pairs(samples.size() - 1);
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) pairs[i] = 0.5 * (samples[i] + samples[i + 1]);
    return summarize(std::move(pairs)).median;
}

MedianInterval medianInterval(std::vector<double> samples, double coverage) {
    const std::size_t n = samples.size();
    std::sort(samples.begin(), samples.end());
    MedianInterval interval;
    double below = 0.0, term = std::pow(0.5, static_cast<double>(n));  // P(B <= k - 1) and P(B = k - 1)
    for (std::size_t k = 1; 2 * k <= n + 1; ++k) {
        below += term;
        term *= static_cast<double>(n - (k - 1)) / static_cast<double>(k);
        const double covered = 1.0 - 2.0 * below;
        if (covered < coverage) break;
        interval = {true, samples[k - 1], samples[n - k], covered};
    }
    return interval;
}

bool framesSettled(const std::vector<double>& frameMs) {
    if (frameMs.size() < 12) return false;
    const auto mid = [&](std::size_t from) {
        return pairedMedian(std::vector<double>(frameMs.end() - static_cast<long>(from), frameMs.end() - static_cast<long>(from) + 6));
    };
    const double last = mid(6), before = mid(12);
    return std::abs(last - before) <= 0.05 * before;
}

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) throw std::invalid_argument("fitLine: x and y differ in length");
    LineFit fit;
    fit.count = x.size();
    if (x.empty()) return fit;
    const double n = static_cast<double>(x.size());
    const double meanX = std::accumulate(x.begin(), x.end(), 0.0) / n, meanY = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double sxx = 0, sxy = 0, syy = 0;  // centred sums: no cancellation between large totals
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxx += (x[i] - meanX) * (x[i] - meanX);
        sxy += (x[i] - meanX) * (y[i] - meanY);
        syy += (y[i] - meanY) * (y[i] - meanY);
    }
    fit.slope = sxx > 0 ? sxy / sxx : 0.0;
    fit.intercept = meanY - fit.slope * meanX;
    if (sxx <= 0) return fit;
    double residual = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double e = y[i] - (fit.intercept + fit.slope * x[i]);
        residual += e * e;
    }
    fit.r2 = syy > 0 ? 1.0 - residual / syy : 1.0;
    return fit;
}

}  // namespace penumbra::bench
