// glTF animation samplers: every interpolation at its keys and between them against hand-computed
// values, the shorter arc for rotations, clamping, equal key times, a single key, long playback, and
// the validation messages the loader will report.

#include "animation/animation_sampler.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace candela::animation {
namespace {

constexpr double kPi = 3.14159265358979323846;

template <size_t N>
std::array<float, N> eval(const AnimationSampler& s, AnimatedProperty property, double time) {
    std::array<float, N> out{};
    EXPECT_EQ(samplerProblem(s, property), "");
    evaluateSampler(s, property, time, out);
    return out;
}

std::array<float, 3> translation(const AnimationSampler& s, double time) {
    return eval<3>(s, AnimatedProperty::Translation, time);
}
std::array<float, 4> rotation(const AnimationSampler& s, double time) { return eval<4>(s, AnimatedProperty::Rotation, time); }
float weight(const AnimationSampler& s, double time) { return eval<1>(s, AnimatedProperty::Weights, time)[0]; }

// The unit quaternion of `degrees` about +Z, (x, y, z, w).
std::array<float, 4> aboutZ(double degrees) {
    const double half = degrees * kPi / 360.0;
    return {0.0f, 0.0f, float(std::sin(half)), float(std::cos(half))};
}

void expectRotation(const std::array<float, 4>& got, const std::array<float, 4>& expected, float tolerance = 1e-6f) {
    // q and −q are the same rotation.
    const float sign = got[0] * expected[0] + got[1] * expected[1] + got[2] * expected[2] + got[3] * expected[3] < 0 ? -1.0f : 1.0f;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(sign * got[c], expected[c], tolerance) << "component " << c;
}

float length(const std::array<float, 4>& q) { return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]); }

const AnimationSampler kSteps{.times = {0, 1, 2}, .values = {0, 0, 0, 1, 2, 3, 5, 5, 5},
                              .interpolation = Interpolation::Step, .width = 3};

TEST(AnimationSampler, StepHoldsEachKeyUntilTheNext) {
    using V = std::array<float, 3>;
    EXPECT_EQ(translation(kSteps, 0.0), (V{0, 0, 0}));
    EXPECT_EQ(translation(kSteps, 0.5), (V{0, 0, 0}));
    EXPECT_EQ(translation(kSteps, 1.0), (V{1, 2, 3}));
    EXPECT_EQ(translation(kSteps, 1.999), (V{1, 2, 3}));
    EXPECT_EQ(translation(kSteps, 2.0), (V{5, 5, 5}));
    // Before the first key and after the last, clamped.
    EXPECT_EQ(translation(kSteps, -3.0), (V{0, 0, 0}));
    EXPECT_EQ(translation(kSteps, 1e9), (V{5, 5, 5}));
}

TEST(AnimationSampler, LinearInterpolatesEachComponent) {
    AnimationSampler s = kSteps;
    s.interpolation = Interpolation::Linear;
    using V = std::array<float, 3>;
    EXPECT_EQ(translation(s, 0.0), (V{0, 0, 0}));
    EXPECT_EQ(translation(s, 0.25), (V{0.25f, 0.5f, 0.75f}));
    EXPECT_EQ(translation(s, 1.0), (V{1, 2, 3}));
    EXPECT_EQ(translation(s, 1.5), (V{3.0f, 3.5f, 4.0f}));
    EXPECT_EQ(translation(s, 2.5), (V{5, 5, 5}));
}

TEST(AnimationSampler, LinearRotationIsSlerp) {
    std::vector<float> values;
    for (float v : aboutZ(0)) values.push_back(v);
    for (float v : aboutZ(90)) values.push_back(v);
    const AnimationSampler s{.times = {0, 1}, .values = values, .interpolation = Interpolation::Linear, .width = 4};
    expectRotation(rotation(s, 0.0), aboutZ(0));
    expectRotation(rotation(s, 0.5), aboutZ(45));
    // Constant angular speed: a normalized lerp of the quaternions would give 21.6° here.
    expectRotation(rotation(s, 0.25), aboutZ(22.5));
    expectRotation(rotation(s, 1.0), aboutZ(90));
}

TEST(AnimationSampler, RotationTakesTheShorterArc) {
    // The second key is stored negated: the same 10° rotation, but 350° away along the longer arc.
    std::vector<float> values;
    for (float v : aboutZ(0)) values.push_back(v);
    for (float v : aboutZ(10)) values.push_back(-v);
    AnimationSampler s{.times = {0, 1}, .values = values, .interpolation = Interpolation::Linear, .width = 4};
    expectRotation(rotation(s, 0.5), aboutZ(5));
    // Near-antipodal keys: −q and q a hair apart. The shorter arc turns by a hair, not by ~360°.
    s.values = {aboutZ(0)[0], aboutZ(0)[1], aboutZ(0)[2], aboutZ(0)[3], -aboutZ(0.001)[0], -aboutZ(0.001)[1],
                -aboutZ(0.001)[2], -aboutZ(0.001)[3]};
    for (double t : {0.1, 0.5, 0.9}) {
        const std::array<float, 4> q = rotation(s, t);
        EXPECT_NEAR(std::fabs(q[3]), 1.0f, 1e-6f) << "at " << t;
        EXPECT_NEAR(length(q), 1.0f, 1e-6f);
    }
}

TEST(AnimationSampler, SlerpMatchesTheClosedFormAtEveryAngle) {
    // The slerp weights are summed from a power series: against sin(sθ)/sin θ in double, from keys
    // a hair apart to keys 180° apart (quaternions at 90°, where the series is longest), about a
    // tilted axis, with keys stored at twice unit length (normalized before interpolating).
    const double axis[3] = {0.48, 0.6, 0.64};  // unit length
    for (double degrees : {0.01, 1.0, 10.0, 45.0, 90.0, 135.0, 170.0, 179.0, 180.0}) {
        for (double scale : {1.0, 2.0}) {
            const double half = degrees * kPi / 360.0;
            const std::vector<float> values{0, 0, 0, float(scale), float(scale * axis[0] * std::sin(half)),
                                            float(scale * axis[1] * std::sin(half)), float(scale * axis[2] * std::sin(half)),
                                            float(scale * std::cos(half))};
            const AnimationSampler s{.times = {0, 1}, .values = values, .interpolation = Interpolation::Linear, .width = 4};
            for (double u : {0.0, 0.1, 0.25, 0.5, 0.7, 0.99, 1.0}) {
                const double angle = u * half;  // the rotation at u is u × degrees about the axis
                const std::array<float, 4> expected{float(axis[0] * std::sin(angle)), float(axis[1] * std::sin(angle)),
                                                    float(axis[2] * std::sin(angle)), float(std::cos(angle))};
                SCOPED_TRACE(::testing::Message() << degrees << "° at " << u << ", keys of length " << scale);
                expectRotation(rotation(s, u), expected, 2e-7f);
            }
        }
    }
}

TEST(AnimationSampler, CubicSplineScalesTangentsByTheKeyInterval) {
    // p(t) = t over two seconds: values 0 and 2, tangents 1 per second. Only tangents scaled by
    // the 2 s interval reproduce the line.
    const AnimationSampler line{.times = {0, 2}, .values = {/*in*/ 0, /*v*/ 0, /*out*/ 1, /*in*/ 1, /*v*/ 2, /*out*/ 0},
                                .interpolation = Interpolation::CubicSpline, .width = 1};
    for (double t : {0.0, 0.5, 1.0, 1.5, 2.0}) EXPECT_NEAR(weight(line, t), t, 1e-6) << t;
    // Flat tangents: the smoothstep 3u² − 2u³ between the values.
    const AnimationSampler ease{.times = {1, 3}, .values = {0, 0, 0, 0, 1, 0},
                                .interpolation = Interpolation::CubicSpline, .width = 1};
    EXPECT_NEAR(weight(ease, 1.5), 0.15625, 1e-6);  // u = 0.25
    EXPECT_NEAR(weight(ease, 2.0), 0.5, 1e-6);
    EXPECT_NEAR(weight(ease, 3.0), 1.0, 1e-6);
    EXPECT_NEAR(weight(ease, 0.0), 0.0, 1e-6);  // clamped to the first key's value, not its tangent
}

TEST(AnimationSampler, CubicSplineRotationOvershootStaysNormalized) {
    std::vector<float> values;
    const auto key = [&](const std::array<float, 4>& q, float tangent) {
        for (int part = 0; part < 3; ++part)
            for (int c = 0; c < 4; ++c) values.push_back(part == 1 ? q[c] : tangent);
    };
    key(aboutZ(0), 5.0f);  // tangents far larger than the keys: the spline leaves the unit sphere
    key(aboutZ(120), -5.0f);
    const AnimationSampler s{.times = {0, 1}, .values = values, .interpolation = Interpolation::CubicSpline, .width = 4};
    for (int i = 0; i <= 20; ++i) {
        const std::array<float, 4> q = rotation(s, i / 20.0);
        EXPECT_NEAR(length(q), 1.0f, 1e-6f) << "at " << i / 20.0;
        for (float c : q) EXPECT_TRUE(std::isfinite(c));
    }
    expectRotation(rotation(s, 1.0), aboutZ(120));
}

TEST(AnimationSampler, EqualKeyTimesJumpWithoutNaN) {
    const AnimationSampler s{.times = {0, 1, 1, 2}, .values = {0, 1, 5, 6}, .interpolation = Interpolation::Linear, .width = 1};
    EXPECT_NEAR(weight(s, 0.999), 0.999, 1e-6);
    EXPECT_EQ(weight(s, 1.0), 5.0f);  // the later key holds from its time on
    EXPECT_EQ(weight(s, 1.5), 5.5f);
    for (Interpolation mode : {Interpolation::Step, Interpolation::Linear}) {
        AnimationSampler m = s;
        m.interpolation = mode;
        for (double t = 0.9; t < 1.1; t += 0.001) EXPECT_TRUE(std::isfinite(weight(m, t)));
    }
}

TEST(AnimationSampler, SingleKeyIsConstant) {
    const AnimationSampler s{.times = {3}, .values = {1, 2, 3}, .interpolation = Interpolation::CubicSpline, .width = 1};
    for (double t : {-1.0, 0.0, 3.0, 100.0}) EXPECT_EQ(weight(s, t), 2.0f);
}

TEST(AnimationSampler, HoursOfPlaybackKeepTheirPhase) {
    // A looping ramp 0 → 1 → 0 over 2 s, played for a million seconds at 60 frames per second.
    const AnimationSampler s{.times = {0, 1, 2}, .values = {0, 1, 0}, .interpolation = Interpolation::Linear, .width = 1};
    EXPECT_EQ(loopTime(1e6 + 0.25, 2.0), 0.25);
    float previous = weight(s, loopTime(1e6, 2.0));
    for (int frame = 1; frame <= 240; ++frame) {
        const float value = weight(s, loopTime(1e6 + frame / 60.0, 2.0));
        ASSERT_TRUE(std::isfinite(value));
        EXPECT_LE(std::fabs(value - previous), 1.0f / 60.0f + 1e-5f) << "a jump at frame " << frame;
        previous = value;
    }
    EXPECT_EQ(loopTime(-0.5, 2.0), 1.5);
    EXPECT_EQ(loopTime(5.0, 0.0), 0.0);
    EXPECT_EQ(loopTime(std::nan(""), 2.0), 0.0);
}

TEST(AnimationSampler, ProblemsNameWhatIsWrong) {
    const auto problem = [](AnimationSampler s, AnimatedProperty p = AnimatedProperty::Translation) {
        return samplerProblem(s, p);
    };
    EXPECT_EQ(problem({.values = {}, .width = 3}), "no keyframes");
    EXPECT_EQ(problem({.times = {0, 2, 1}, .values = std::vector<float>(9), .width = 3}),
              "key times decrease at key 2 (1.000000 s after 2.000000 s)");
    EXPECT_EQ(problem({.times = {0, std::nanf("")}, .values = std::vector<float>(6), .width = 3}), "key time 1 is not finite");
    EXPECT_EQ(problem({.times = {0, 1}, .values = std::vector<float>(6), .interpolation = Interpolation::CubicSpline, .width = 3}),
              "6 output values for 2 keys (expected 18)");
    EXPECT_EQ(problem({.times = {0}, .values = {0, INFINITY, 0}, .width = 3}), "output value 1 is not finite");
    EXPECT_EQ(problem({.times = {0}, .values = {0, 0, 0}, .width = 3}, AnimatedProperty::Rotation),
              "values of 3 components (expected 4)");
    EXPECT_EQ(problem({.times = {0}, .values = {}, .width = 0}, AnimatedProperty::Weights),
              "values of 0 components (expected at least 1)");
    EXPECT_EQ(problem({.times = {0, 1, 1}, .values = std::vector<float>(3), .width = 1}, AnimatedProperty::Weights), "");
    // KHR_animation_pointer: plain values of 1 to 4 floats; a visibility is one value, STEP only.
    EXPECT_EQ(problem({.times = {0}, .values = std::vector<float>(5), .width = 5}, AnimatedProperty::Values),
              "values of 5 components (expected 1 to 4)");
    EXPECT_EQ(problem({.times = {0, 1}, .values = {0, 1}, .width = 1}, AnimatedProperty::Visibility),
              "a visibility (a bool) takes STEP interpolation, not LINEAR");
    EXPECT_EQ(problem({.times = {0, 1}, .values = {0, 1, 0, 1}, .interpolation = Interpolation::Step, .width = 2},
                      AnimatedProperty::Visibility),
              "values of 2 components (expected 1)");
    EXPECT_EQ(problem({.times = {0, 1}, .values = {0, 1}, .interpolation = Interpolation::Step, .width = 1}, AnimatedProperty::Visibility),
              "");
}

// Values are interpolated per component and never normalized (a 4-wide value is not a rotation).
TEST(AnimationSampler, PlainValuesInterpolatePerComponent) {
    const AnimationSampler linear{.times = {0, 2}, .values = {0, 0, 0, 2, 4, 8, 2, 0}, .width = 4};
    const std::array<float, 4> v = eval<4>(linear, AnimatedProperty::Values, 0.5);
    EXPECT_FLOAT_EQ(v[0], 1.0f);  // a quarter of the way from (0, 0, 0, 2) to (4, 8, 2, 0)
    EXPECT_FLOAT_EQ(v[1], 2.0f);
    EXPECT_FLOAT_EQ(v[2], 0.5f);
    EXPECT_FLOAT_EQ(v[3], 1.5f);
    // Flat tangents: the smoothstep, 0.15625 at a quarter of the interval.
    const AnimationSampler cubic{.times = {0, 1}, .values = {0, 0, 0, 0, 10, 0}, .interpolation = Interpolation::CubicSpline, .width = 1};
    EXPECT_NEAR(eval<1>(cubic, AnimatedProperty::Values, 0.25)[0], 1.5625f, 1e-5f);
    const AnimationSampler step{.times = {0, 1, 2}, .values = {1, 0, 1}, .interpolation = Interpolation::Step, .width = 1};
    EXPECT_EQ(eval<1>(step, AnimatedProperty::Visibility, 0.999)[0], 1.0f);
    EXPECT_EQ(eval<1>(step, AnimatedProperty::Visibility, 1.0)[0], 0.0f);
}

}  // namespace
}  // namespace candela::animation
