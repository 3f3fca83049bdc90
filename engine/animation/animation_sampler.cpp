#include "animation/animation_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela::animation {

namespace {

using Quat = std::array<double, 4>;  // x, y, z, w

// The first float of key `key`'s value (for CubicSpline the value between the two tangents).
const float* keyValue(const AnimationSampler& s, size_t key) {
    const size_t w = s.width;
    return s.interpolation == Interpolation::CubicSpline ? s.values.data() + (3 * key + 1) * w : s.values.data() + key * w;
}

Quat quat(const float* v) { return {v[0], v[1], v[2], v[3]}; }

// Scales q to unit length; a zero quaternion (no rotation can be read from it) becomes the identity.
void normalize(Quat& q) {
    const double length2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    // Keys are stored unit length to float precision, and slerp keeps that: near unit length one
    // Newton step of 1/√x from 1 is exact to (length² − 1)², below 1e-12 here — no square root or
    // division (this runs for every rotation channel every frame).
    double inverse = 1.5 - 0.5 * length2;
    if (!(std::abs(length2 - 1.0) < 1e-6)) {
        if (!(length2 > 1e-60)) {
            q = {0.0, 0.0, 0.0, 1.0};
            return;
        }
        inverse = 1.0 / std::sqrt(length2);
    }
    for (double& v : q) v *= inverse;
}

void store(const Quat& q, std::span<float> out) {
    for (int c = 0; c < 4; ++c) out[c] = float(q[c]);
}

// sin(tθ) / sin θ for t in [0, 1] and x = cos θ in [0, 1], from its power series in (x − 1)
// (D. Eberly, "A Fast and Accurate Algorithm for Computing SLERP", JGT 2011): term i is term i − 1
// times (t² − i²)(x − 1) / (i(2i + 1)). Every term is ≥ 0 and at most half the one before, so the
// sum stops once a term adds less than 1e-13 of it: a handful of terms for the angles between
// neighbouring keys, about forty at θ = 90°, and no acos or sin. Exact at t = 0, at t = 1 (the
// second term is 0) and at x = 1.
constexpr int kSlerpTerms = 64;  // 2⁻⁶⁴ < 1e-13 even at θ = 90°
constexpr std::array<double, kSlerpTerms + 1> kSlerpDivisors = [] {
    std::array<double, kSlerpTerms + 1> out{};
    for (int i = 1; i <= kSlerpTerms; ++i) out[size_t(i)] = 1.0 / double(i * (2 * i + 1));
    return out;
}();

// The weights sin((1 − s)θ) / sin θ and sin(sθ) / sin θ of the two keys, summed side by side.
std::array<double, 2> slerpWeights(double s, double xMinus1) {
    const double t[2] = {1.0 - s, s};
    double term[2] = {t[0], t[1]}, sum[2] = {t[0], t[1]};
    for (int i = 1; i <= kSlerpTerms && (term[0] > 1e-13 * sum[0] || term[1] > 1e-13 * sum[1]); ++i) {
        const double common = xMinus1 * kSlerpDivisors[size_t(i)], i2 = double(i) * double(i);
        for (int k = 0; k < 2; ++k) {
            term[k] *= (t[k] * t[k] - i2) * common;
            sum[k] += term[k];
        }
    }
    return {sum[0], sum[1]};
}

// Spherical interpolation along the shorter arc (q and −q are the same rotation).
Quat slerp(Quat a, Quat b, double s) {
    // Keys unit length to float rounding are interpolated as they are, and the result normalized:
    // that differs from normalizing them first by ~1e-7 at most, below the float output's precision.
    const auto nearUnit = [](const Quat& q) { return std::abs(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] - 1.0) < 1e-6; };
    if (!nearUnit(a) || !nearUnit(b)) normalize(a), normalize(b);
    double cosine = std::min(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3], 1.0);
    if (cosine < 0.0) {
        for (double& v : b) v = -v;
        cosine = -cosine;
    }
    const std::array<double, 2> w = slerpWeights(s, cosine - 1.0);
    Quat q;
    for (int c = 0; c < 4; ++c) q[c] = w[0] * a[c] + w[1] * b[c];
    normalize(q);
    return q;
}

void writeKey(const AnimationSampler& s, AnimatedProperty property, size_t key, std::span<float> out) {
    const float* v = keyValue(s, key);
    if (property == AnimatedProperty::Rotation) {
        Quat q = quat(v);
        normalize(q);
        return store(q, out);
    }
    std::copy(v, v + s.width, out.begin());
}

}  // namespace

std::string samplerProblem(const AnimationSampler& s, AnimatedProperty property) {
    if (s.times.empty()) return "no keyframes";
    uint32_t expected = 3;  // 0: at least 1
    switch (property) {
        case AnimatedProperty::Translation:
        case AnimatedProperty::Scale: break;
        case AnimatedProperty::Rotation: expected = 4; break;
        case AnimatedProperty::Weights: expected = 0; break;
        case AnimatedProperty::Weight:
        case AnimatedProperty::Visibility: expected = 1; break;
        case AnimatedProperty::Values:
            if (s.width < 1 || s.width > 4)
                return "values of " + std::to_string(s.width) + " components (expected 1 to 4)";
            expected = s.width;
            break;
    }
    if (s.width == 0 || (expected != 0 && s.width != expected))
        return "values of " + std::to_string(s.width) + " components (expected " +
               (expected ? std::to_string(expected) : std::string("at least 1")) + ")";
    if (property == AnimatedProperty::Visibility && s.interpolation != Interpolation::Step)
        return std::string("a visibility (a bool) takes STEP interpolation, not ") +
               (s.interpolation == Interpolation::Linear ? "LINEAR" : "CUBICSPLINE");
    for (size_t k = 0; k < s.times.size(); ++k) {
        if (!std::isfinite(s.times[k])) return "key time " + std::to_string(k) + " is not finite";
        if (k > 0 && s.times[k] < s.times[k - 1])
            return "key times decrease at key " + std::to_string(k) + " (" + std::to_string(s.times[k]) + " s after " +
                   std::to_string(s.times[k - 1]) + " s)";
    }
    const size_t perKey = size_t(s.width) * (s.interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (s.values.size() != s.times.size() * perKey)
        return std::to_string(s.values.size()) + " output values for " + std::to_string(s.times.size()) + " keys (expected " +
               std::to_string(s.times.size() * perKey) + ")";
    for (size_t i = 0; i < s.values.size(); ++i)
        if (!std::isfinite(s.values[i])) return "output value " + std::to_string(i) + " is not finite";
    return {};
}

void evaluateSampler(const AnimationSampler& s, AnimatedProperty property, double time, std::span<float> out) {
    const size_t last = s.times.size() - 1;
    if (!(time > double(s.times.front())) || last == 0) return writeKey(s, property, 0, out);  // NaN too
    if (time >= double(s.times[last])) return writeKey(s, property, last, out);
    // The interval [t_k, t_k+1) holding `time`; with equal key times, the later key's interval.
    const size_t k = size_t(std::upper_bound(s.times.begin(), s.times.end(), time,
                                             [](double t, float key) { return t < double(key); }) -
                            s.times.begin()) - 1;
    if (s.interpolation == Interpolation::Step) return writeKey(s, property, k, out);
    const double t0 = s.times[k], dt = double(s.times[k + 1]) - t0;  // > 0: t0 ≤ time < t1
    const double u = (time - t0) / dt;
    const bool rotation = property == AnimatedProperty::Rotation;
    const size_t w = s.width;
    const float* v0 = keyValue(s, k);
    const float* v1 = keyValue(s, k + 1);
    if (s.interpolation == Interpolation::Linear && rotation) return store(slerp(quat(v0), quat(v1), u), out);
    if (s.interpolation == Interpolation::Linear) {
        for (size_t c = 0; c < w; ++c) out[c] = float((1.0 - u) * v0[c] + u * v1[c]);
        return;
    }
    // Cubic Hermite spline (glTF 2.0 Appendix C): tangents are per second, so scaled by the interval.
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    const float* out0 = v0 + w;  // key k's out-tangent
    const float* in1 = v1 - w;   // key k + 1's in-tangent
    Quat q{};
    for (size_t c = 0; c < w; ++c) {
        const double v = h00 * v0[c] + h10 * dt * out0[c] + h01 * v1[c] + h11 * dt * in1[c];
        if (rotation) q[c] = v;
        else out[c] = float(v);
    }
    if (!rotation) return;
    normalize(q);
    store(q, out);
}

double loopTime(double time, double duration) {
    if (!(duration > 0.0) || !std::isfinite(time) || !std::isfinite(duration)) return 0.0;
    double phase = std::fmod(time, duration);
    if (phase < 0.0) phase += duration;
    return phase < duration ? phase : 0.0;
}

}  // namespace candela::animation
