// The bench's least-squares line (shadow pass against triangles drawn) against values worked out
// by hand, and which cases the report fits.
#include "bench/Report.h"
#include "bench/Statistics.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace penumbra::bench {
namespace {

TEST(FitLine, PointsOnALineGiveItWithRSquaredOne) {
    const LineFit f = fitLine({1, 2, 3, 4}, {5, 8, 11, 14});  // y = 2 + 3x
    EXPECT_EQ(f.count, 4u);
    EXPECT_NEAR(f.slope, 3.0, 1e-12);
    EXPECT_NEAR(f.intercept, 2.0, 1e-12);
    EXPECT_NEAR(f.r2, 1.0, 1e-12);
}

TEST(FitLine, ScatteredPointsGiveTheLeastSquaresLineAndTheShareOfVarianceItExplains) {
    // x̄ = 3, ȳ = 4: Sxy = 6, Sxx = 10, so slope 0.6 and intercept 2.2; the residuals
    // (-0.8, 0.6, 1, -0.6, -0.2) square to 2.4 against a total of 6: R² = 0.6.
    const LineFit f = fitLine({1, 2, 3, 4, 5}, {2, 4, 5, 4, 5});
    EXPECT_NEAR(f.slope, 0.6, 1e-12);
    EXPECT_NEAR(f.intercept, 2.2, 1e-12);
    EXPECT_NEAR(f.r2, 0.6, 1e-12);
}

TEST(FitLine, MillionsOfTrianglesKeepTheirPrecision) {
    // Centred sums: x around 1e6 with ms around 100 must not lose the slope to cancellation.
    const LineFit f = fitLine({1e6, 1e6 + 1, 1e6 + 2}, {100.0, 100.5, 101.0});
    EXPECT_NEAR(f.slope, 0.5, 1e-9);
    EXPECT_NEAR(f.r2, 1.0, 1e-9);
}

TEST(FitLine, OneDistinctXExplainsNothing) {
    const LineFit f = fitLine({7, 7, 7}, {1, 2, 6});
    EXPECT_EQ(f.slope, 0.0);
    EXPECT_NEAR(f.intercept, 3.0, 1e-12);
    EXPECT_EQ(f.r2, 0.0);
    EXPECT_THROW(fitLine({1, 2}, {1}), std::invalid_argument);
}

CaseResult result(const std::string& suite, const std::string& technique, double triangles, double shadowMs) {
    CaseResult r;
    r.spec.suite = suite;
    r.technique = technique;
    r.shadowTrianglesPerFrame = triangles;
    r.passMs[static_cast<std::size_t>(render::Pass::Shadow)].median = shadowMs;
    return r;
}

TEST(ShadowPassScaling, FitsEachLabelThatDrewThreeDifferentTriangleCounts) {
    std::vector<CaseResult> results;
    for (const double t : {1e4, 1e5, 1e6}) {
        results.push_back(result("triangle-scaling", "hard", t, 1.0 + 1e-4 * t));  // 0.1 ms per 1000 triangles
        results.push_back(result("triangle-scaling", "none", 0, 0.05));           // draws no map
        results.push_back(result("other", "hard", t, 2.0 + 2e-4 * t));            // another suite: its own line
    }
    results.push_back(result("triangle-scaling", "cascaded", 1e4, 3));  // two scenes only
    results.push_back(result("triangle-scaling", "cascaded", 1e5, 9));
    results.push_back(result("triangle-scaling", "lispsm", 1e5, 4));    // three runs, one triangle count
    results.push_back(result("triangle-scaling", "lispsm", 1e5, 5));
    results.push_back(result("triangle-scaling", "lispsm", 1e5, 6));

    const std::vector<ScalingFit> fits = shadowPassScaling(results);
    ASSERT_EQ(fits.size(), 2u);
    EXPECT_EQ(fits[0].suite, "triangle-scaling");
    EXPECT_EQ(fits[0].label, "hard");
    EXPECT_EQ(fits[0].fit.count, 3u);
    EXPECT_NEAR(fits[0].fit.slope * 1e6, 100.0, 1e-9);  // ms per million triangles
    EXPECT_NEAR(fits[0].fit.intercept, 1.0, 1e-9);
    EXPECT_NEAR(fits[0].fit.r2, 1.0, 1e-12);
    EXPECT_EQ(fits[1].suite, "other");
    EXPECT_NEAR(fits[1].fit.slope * 1e6, 200.0, 1e-9);
}

CaseResult floorCase(const std::string& technique, const std::string& scene, double frameMs, double shadowMs, std::size_t memory) {
    CaseResult r = result("floor", technique, 0, shadowMs);
    r.spec.scene = scene;
    r.sceneName = scene;
    r.frameMs.mean = frameMs;
    r.shadowMemoryBytes = memory;
    return r;
}

TEST(FloorRatios, DivideEachCaseByTheFloorOfItsOwnSceneAndKind) {
    CaseResult hardWithTwoLights = floorCase("hard", "a", 50, 2, 48);
    hardWithTwoLights.resolutions = {2048, 1024};
    const std::vector<CaseResult> results{
        floorCase(kFloorDepth, "a", 6, 4, 16), floorCase(kFloorLambert, "a", 20, 4, 16), floorCase(kFloorUnshadowed, "a", 5, 0, 0),
        floorCase("none", "a", 30, 0, 0),      hardWithTwoLights,
        floorCase("hard", "b", 70, 9, 48),  // no floor ran on scene b
    };
    const std::vector<FloorRatio> ratios = floorRatios(results);
    ASSERT_EQ(ratios.size(), 2u);
    EXPECT_EQ(ratios[0].label, "none");  // no map: against the unshadowed floor, no shadow pass ratio
    EXPECT_EQ(ratios[0].frameFloor, kFloorUnshadowed);
    EXPECT_DOUBLE_EQ(ratios[0].frame, 6.0);
    EXPECT_EQ(ratios[0].shadowPass, 0.0);
    EXPECT_EQ(ratios[1].label, "hard");
    EXPECT_EQ(ratios[1].frameFloor, kFloorLambert);
    EXPECT_DOUBLE_EQ(ratios[1].frame, 2.5);
    EXPECT_DOUBLE_EQ(ratios[1].shadowPass, 0.5);
    EXPECT_EQ(ratios[1].lights, 2u);
}

// With --rounds, each round's case goes against the floor of its own round (round 1's floor had
// divided every round: the 98k grid's vsm read 0.72x floor-depth where its own rounds gave
// 0.92-0.95); with --calibrate on both, the shadow pass by the glFinish wall clocks, which
// llvmpipe's queries can misplace (floor-depth's query 7-19 ms a frame, its wall 10.6-10.9).
TEST(FloorRatios, TakeTheFloorOfTheCasesOwnRoundAndItsWallClockWhenCalibrated) {
    const auto inRound = [](CaseResult r, int round) {
        r.spec.round = round;
        return r;
    };
    const std::vector<CaseResult> results{
        inRound(floorCase(kFloorDepth, "a", 6, 4, 16), 0), inRound(floorCase("vsm", "a", 50, 2, 48), 0),
        inRound(floorCase(kFloorDepth, "a", 6, 8, 16), 1), inRound(floorCase("vsm", "a", 50, 2, 48), 1)};
    std::vector<FloorRatio> ratios = floorRatios(results);
    ASSERT_EQ(ratios.size(), 2u);
    EXPECT_DOUBLE_EQ(ratios[0].shadowPass, 0.5);
    EXPECT_DOUBLE_EQ(ratios[1].shadowPass, 0.25) << "round 2 against round 2's floor";
    EXPECT_EQ(ratios[1].round, 1);
    EXPECT_FALSE(ratios[1].shadowPassByWall);

    std::vector<CaseResult> calibrated = results;
    const auto shadow = static_cast<std::size_t>(render::Pass::Shadow);
    for (CaseResult& r : calibrated) {
        r.calibrated = true;
        r.calibration[shadow].wallMs = r.technique == kFloorDepth ? 10.0 : 12.0;
    }
    ratios = floorRatios(calibrated);
    ASSERT_EQ(ratios.size(), 2u);
    EXPECT_DOUBLE_EQ(ratios[0].shadowPass, 1.2);
    EXPECT_DOUBLE_EQ(ratios[1].shadowPass, 1.2);
    EXPECT_TRUE(ratios[1].shadowPassByWall);
    calibrated[2].calibrated = false;  // round 2's floor measured by its queries alone: both by queries
    EXPECT_DOUBLE_EQ(floorRatios(calibrated)[1].shadowPass, 0.25);
}

// Two frames in flight let a frame's wall time move into its neighbour's (llvmpipe, hard on
// scenes/glass.json: 8-23 and 83-113 ms in turn): the plain median of an odd count lands on one
// side, the median over consecutive pairs on their mean.
TEST(PairedMedian, AlternatingFramesGiveTheirPairsMean) {
    const std::vector<double> alternating = {16, 110, 18, 106, 20, 104, 17};
    EXPECT_DOUBLE_EQ(summarize(alternating).median, 20.0);
    EXPECT_DOUBLE_EQ(pairedMedian(alternating), 62.5);  // of 63, 64, 62, 63, 62, 60.5
    // One slow frame (a compile, a page fault) among even ones moves two pairs, not the middle.
    EXPECT_DOUBLE_EQ(pairedMedian({50, 50, 50, 500, 50, 50, 50}), 50.0);
    EXPECT_DOUBLE_EQ(pairedMedian({42}), 42.0);
    EXPECT_DOUBLE_EQ(pairedMedian({}), 0.0);
}

// The warm-up's end: frames alternating short and long around a steady mean have settled (the
// plain median of 5 of them swings between the two sides); frames still getting faster have not.
TEST(FramesSettled, AlternatingFramesSettleAndFallingOnesDoNot) {
    std::vector<double> alternating;
    for (int i = 0; i < 13; ++i) alternating.push_back(i % 2 ? 110.0 : 16.0);
    EXPECT_TRUE(framesSettled(alternating));
    std::vector<double> falling;
    for (int i = 0; i < 13; ++i) falling.push_back(100.0 - 4.0 * i);
    EXPECT_FALSE(framesSettled(falling));
    EXPECT_FALSE(framesSettled(std::vector<double>(11, 50.0)));  // too few to tell
    EXPECT_TRUE(framesSettled(std::vector<double>(12, 50.0)));
}

// `bench --rounds`' interval for a median ratio (from 6 rounds), against counts worked out by hand.
TEST(MedianInterval, TakesTheOrderStatisticsThatABinomialCountPutsTheMedianBetween) {
    // 12 rounds: P(B <= 2) = (1 + 12 + 66) / 4096, so x(3) and x(10) hold the median with 1 - 2 x 79/4096.
    const MedianInterval twelve = medianInterval({12, 3, 1, 5, 7, 9, 11, 2, 4, 6, 8, 10});
    ASSERT_TRUE(twelve.found);
    EXPECT_EQ(twelve.low, 3.0);
    EXPECT_EQ(twelve.high, 10.0);
    EXPECT_DOUBLE_EQ(twelve.coverage, 1.0 - 2.0 * 79.0 / 4096.0);
    // 6 rounds: only the extremes, 1 - 2/64; 5 rounds: 1 - 2/32 < 95 %, none.
    const MedianInterval six = medianInterval({1.2, 1.0, 1.1, 1.3, 0.9, 1.25});
    ASSERT_TRUE(six.found);
    EXPECT_EQ(six.low, 0.9);
    EXPECT_EQ(six.high, 1.3);
    EXPECT_DOUBLE_EQ(six.coverage, 1.0 - 2.0 / 64.0);
    EXPECT_FALSE(medianInterval({1, 2, 3, 4, 5}).found);
    EXPECT_FALSE(medianInterval({}).found);
    EXPECT_TRUE(medianInterval({1, 2, 3, 4, 5}, 0.9).found);
}

// `bench --rounds`: the list {none, hard} on scene a and {hard} on scene b, three rounds. Within a
// round the machine's speed moves every case alike (here by a factor per round), so the ratios to
// each scene's first case hold while the frame times swing.
TEST(RoundRatios, DivideEachCaseByItsScenesFirstCaseRoundByRoundAndTakeTheMedians) {
    std::vector<CaseResult> results;
    const double speed[3] = {1.0, 2.0, 0.5};
    for (int round = 0; round < 3; ++round)
        for (const auto& [technique, scene, ms] : {std::tuple{"none", "a", 10.0}, std::tuple{"hard", "a", 15.0}, std::tuple{"hard", "b", 7.0}}) {
            CaseResult r = floorCase(technique, scene, 0, 0, 0);
            r.spec.round = round;
            const double frame = ms * speed[round] * (round == 1 && std::string(technique) == "hard" ? 1.2 : 1.0);
            // Frames alternating short and long around it, as two frames in flight can make them.
            r.frameSamples = {0.25 * frame, 1.75 * frame, 0.25 * frame, 1.75 * frame, 0.25 * frame};
            results.push_back(r);
        }
    const std::vector<RoundRatio> rows = roundRatios(results);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].label, "none");
    EXPECT_EQ(rows[0].medianRatio, 1.0);
    EXPECT_EQ(rows[1].label, "hard");
    EXPECT_EQ(rows[1].base, "none");
    ASSERT_EQ(rows[1].ratios.size(), 3u);
    EXPECT_DOUBLE_EQ(rows[1].ratios[1], 1.8);   // 15 x 2 x 1.2 against 10 x 2
    EXPECT_DOUBLE_EQ(rows[1].medianRatio, 1.5);  // of 1.5, 1.8, 1.5
    EXPECT_DOUBLE_EQ(rows[1].medianFrameMs, 15.0);  // of 15, 36, 7.5
    EXPECT_FALSE(rows[1].ratioInterval.found);  // 3 rounds are too few for 95 %
    EXPECT_EQ(rows[2].sceneName, "b");
    EXPECT_EQ(rows[2].base, "hard");  // scene b's first case is itself
    EXPECT_EQ(rows[2].medianRatio, 1.0);

    results.pop_back();  // not whole rounds of one list
    EXPECT_TRUE(roundRatios(results).empty());
    results.resize(3);  // one round
    EXPECT_TRUE(roundRatios(results).empty());
}

}  // namespace
}  // namespace penumbra::bench
