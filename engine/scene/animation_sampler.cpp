#include "scene/animation_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela::scene {

namespace {

using Quat = std::array<double, 4>;  // x, y, z, w

// Value `key` of the sampler, component `c`; `part` selects in-tangent (0), value (1) or
// out-tangent (2) of a cubic-spline key and is ignored otherwise.
double at(const AnimationSampler& s, size_t key, uint32_t c, int part = 1) {
    const size_t w = s.width;
    if (s.interpolation == Interpolation::CubicSpline) return s.values[(3 * key + size_t(part)) * w + c];
    return s.values[key * w + c];
}

Quat quat(const AnimationSampler& s, size_t key) { return {at(s, key, 0), at(s, key, 1), at(s, key, 2), at(s, key, 3)}; }

// Unit length; a zero quaternion (no rotation can be read from it) becomes the identity.
Quat normalized(Quat q) {
    const double length2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    // Keys are stored unit length to float precision: leave those as they are (this runs several
    // times per rotation channel per frame).
    if (std::abs(length2 - 1.0) < 1e-14) return q;
    if (!(length2 > 1e-60)) return {0.0, 0.0, 0.0, 1.0};
    const double inverse = 1.0 / std::sqrt(length2);
    for (double& v : q) v *= inverse;
    return q;
}

// Spherical interpolation along the shorter arc (q and −q are the same rotation).
Quat slerp(Quat a, Quat b, double s) {
    // The angle between the keys from their dot product over the product of their lengths (one
    // square root, not two); keys off unit length by float rounding are interpolated as they are
    // and the result normalized, which differs from normalizing them first by ~1e-7 at most.
    double la = a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3];
    double lb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3];
    if (!(std::abs(la - 1.0) < 1e-3) || !(std::abs(lb - 1.0) < 1e-3)) {
        a = normalized(a);  // far from unit, or zero: normalize properly
        b = normalized(b);
        la = lb = 1.0;
    }
    double cosine = std::min((a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]) / std::sqrt(la * lb), 1.0);
    if (cosine < 0.0) {
        for (double& v : b) v = -v;
        cosine = -cosine;
    }
    double wa = 1.0 - s, wb = s;
    // Nearly the same rotation: sin θ → 0, and linear interpolation is exact to rounding.
    if (cosine < 1.0 - 1e-9) {
        const double theta = std::acos(cosine);
        const double sine = std::sqrt(1.0 - cosine * cosine);  // sin θ for θ in [0, π/2]
        wa = std::sin((1.0 - s) * theta) / sine;
        wb = std::sin(s * theta) / sine;
    }
    Quat q;
    for (int c = 0; c < 4; ++c) q[c] = wa * a[c] + wb * b[c];
    return normalized(q);
}

void writeKey(const AnimationSampler& s, AnimatedProperty property, size_t key, std::span<float> out) {
    if (property == AnimatedProperty::Rotation) {
        const Quat q = normalized(quat(s, key));
        for (int c = 0; c < 4; ++c) out[c] = float(q[c]);
        return;
    }
    for (uint32_t c = 0; c < s.width; ++c) out[c] = float(at(s, key, c));
}

}  // namespace

std::string samplerProblem(const AnimationSampler& s, AnimatedProperty property) {
    if (s.times.empty()) return "no keyframes";
    const uint32_t expected = property == AnimatedProperty::Rotation ? 4 : property == AnimatedProperty::Weights ? 0 : 3;
    if (s.width == 0 || (expected != 0 && s.width != expected))
        return "values of " + std::to_string(s.width) + " components (expected " +
               (expected ? std::to_string(expected) : std::string("at least 1")) + ")";
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
    if (s.interpolation == Interpolation::Linear && rotation) {
        const Quat q = slerp(quat(s, k), quat(s, k + 1), u);
        for (int c = 0; c < 4; ++c) out[c] = float(q[c]);
        return;
    }
    if (s.interpolation == Interpolation::Linear) {
        for (uint32_t c = 0; c < s.width; ++c) out[c] = float((1.0 - u) * at(s, k, c) + u * at(s, k + 1, c));
        return;
    }
    // Cubic Hermite spline (glTF 2.0 Appendix C): tangents are per second, so scaled by the interval.
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    Quat q{};
    for (uint32_t c = 0; c < s.width; ++c) {
        const double v = h00 * at(s, k, c) + h10 * dt * at(s, k, c, 2) + h01 * at(s, k + 1, c) + h11 * dt * at(s, k + 1, c, 0);
        if (rotation) q[c] = v;
        else out[c] = float(v);
    }
    if (!rotation) return;
    q = normalized(q);
    for (int c = 0; c < 4; ++c) out[c] = float(q[c]);
}

double loopTime(double time, double duration) {
    if (!(duration > 0.0) || !std::isfinite(time) || !std::isfinite(duration)) return 0.0;
    double phase = std::fmod(time, duration);
    if (phase < 0.0) phase += duration;
    return phase < duration ? phase : 0.0;
}

}  // namespace candela::scene
