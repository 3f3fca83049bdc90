#include "reports/ibl_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace candela::reports::reference {
namespace {

constexpr double kMinNoV = 1e-4;
constexpr double kMirrorRoughness = 1e-4;  // below: the mirror (α < 1e-8)
constexpr double kSnap = 1e-9;             // bilinear: texel fractions this close to a centre snap to it

// ---- Gauss-Legendre quadrature ----

constexpr int kOrder = 8;  // nodes per panel

struct GaussLegendre {
    std::array<double, kOrder> x{};  // nodes on [−1, 1]
    std::array<double, kOrder> w{};  // weights, summing to 2
};

// The kOrder-point rule, by Newton's iteration on the Legendre polynomial P_kOrder.
GaussLegendre makeGaussLegendre() {
    GaussLegendre rule;
    for (int i = 0; i < kOrder; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (kOrder + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;  // P_0, P_1, ... by the three-term recurrence
            for (int k = 2; k <= kOrder; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = kOrder * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) break;
        }
        rule.x[size_t(i)] = x;
        rule.w[size_t(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return rule;
}

const GaussLegendre& gaussLegendre() {
    static const GaussLegendre rule = makeGaussLegendre();
    return rule;
}

// Σ f(x)·weight over `panels` equal panels of [lo, hi], kOrder Gauss-Legendre nodes each.
template <class F>
void forEachNode(double lo, double hi, int panels, F&& f) {
    const GaussLegendre& rule = gaussLegendre();
    const double width = (hi - lo) / panels;
    for (int p = 0; p < panels; ++p) {
        const double centre = lo + (p + 0.5) * width;
        for (int i = 0; i < kOrder; ++i) f(centre + 0.5 * width * rule.x[size_t(i)], 0.5 * width * rule.w[size_t(i)]);
    }
}

// ---- Split sum ----

// Outer variable s = ln(tan θh / α): the GGX inverse-CDF variable ξ = 1 / (1 + e^(−2s)), so
// dξ = ds / (2 cosh² s). Below kMinS (θh < 4.5e-5 α) the neglected mass is ξ < e^(2·kMinS) ≈ 2e-9
// with an integrand → NoV / √(NoV² (1 − α²) + α²) ≤ 1; above kMaxS it is 1 − ξ < e^(−2·kMaxS) ≈ 1e-21
// with an integrand ≤ 2/NoV² ≤ 2e8 (V ≤ 1/(4 n·l n·v), and n·l > 0 needs n·h > n·v/2).
constexpr double kMinS = -10.0;
constexpr double kMaxS = 24.0;
constexpr double kPanelWidthS = 1.0;     // s panels (at refinement 1)
constexpr int kFullPhiPoints = 24;       // trapezoid intervals on [0, π] where every φ has n·l > 0
constexpr int kPartialPhiPanels = 3;     // Gauss-Legendre panels in t where only φ < φmax has n·l > 0

struct SplitSumAccumulator {
    double NoV, sinThetaV, alpha2;
    double a = 0.0, b = 0.0;

    // Adds weight × (1 − Fc, Fc) × V·4(n·l)(v·h)/(n·h) for the half vector at (θh, φ).
    void add(double cosThetaH, double sinThetaH, double cosPhi, double weight) {
        const double VoH = sinThetaV * sinThetaH * cosPhi + NoV * cosThetaH;
        const double NoL = 2.0 * VoH * cosThetaH - NoV;
        if (NoL <= 0.0 || VoH <= 0.0) return;
        const double vis = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - alpha2) + alpha2) +
                                  NoV * std::sqrt(NoL * NoL * (1.0 - alpha2) + alpha2));
        const double g = vis * 4.0 * NoL * VoH / cosThetaH * weight;
        const double x = 1.0 - VoH;
        const double fc = x * x * x * x * x;
        a += (1.0 - fc) * g;
        b += fc * g;
    }
};

SplitSum mirror(double NoV) {
    const double x = 1.0 - NoV;
    const double fc = x * x * x * x * x;
    return {1.0 - fc, fc};
}

}  // namespace

SplitSum splitSumRefined(double NoV, double roughness, int refinement) {
    NoV = std::clamp(NoV, kMinNoV, 1.0);
    roughness = std::clamp(roughness, 0.0, 1.0);
    refinement = std::max(refinement, 1);
    if (roughness < kMirrorRoughness) return mirror(NoV);
    const double alpha = roughness * roughness;
    SplitSumAccumulator acc{NoV, std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), alpha * alpha};

    // v = (sin θv, 0, cos θv), n = +Z. l = reflect(−v, h) is above the horizon for every φ while
    // θh < π/4 − θv/2 and for none from θh ≥ π/4 + θv/2; in between for cos φ > c(θh) with
    // c = −cot θv cot 2θh. tan(π/4 ∓ θv/2) = cos θv / (1 ± sin θv).
    const double sFull = std::log(NoV / (1.0 + acc.sinThetaV) / alpha);
    const double sEnd = std::log((1.0 + acc.sinThetaV) / NoV / alpha);

    const auto outer = [&](double lo, double hi, auto&& inner) {
        lo = std::max(lo, kMinS);
        hi = std::min(hi, kMaxS);
        if (hi <= lo) return;
        const int panels = std::max(1, int(std::ceil((hi - lo) / kPanelWidthS))) * refinement;
        forEachNode(lo, hi, panels, [&](double s, double ws) {
            const double tanThetaH = alpha * std::exp(s);
            const double cosThetaH = 1.0 / std::sqrt(1.0 + tanThetaH * tanThetaH);
            const double sinThetaH = tanThetaH * cosThetaH;
            const double coshS = std::cosh(s);
            // dξ1 = ds / (2 cosh² s); dξ2 = dφ / 2π over [0, 2π] = dφ / π over [0, π] (symmetry).
            inner(cosThetaH, sinThetaH, ws / (2.0 * coshS * coshS) / std::numbers::pi);
        });
    };

    // Every φ: the integrand is smooth and 2π-periodic in φ, even about 0 and π, so the trapezoid
    // rule on [0, π] (endpoints halved) converges geometrically.
    const int phiSteps = kFullPhiPoints * refinement;
    std::vector<double> fullPhiCos, fullPhiWeight;
    for (int i = 0; i <= phiSteps; ++i) {
        const double step = std::numbers::pi / phiSteps;
        fullPhiCos.push_back(std::cos(i * step));
        fullPhiWeight.push_back((i == 0 || i == phiSteps) ? 0.5 * step : step);
    }
    outer(kMinS, sFull, [&](double cosThetaH, double sinThetaH, double weight) {
        for (size_t i = 0; i < fullPhiCos.size(); ++i) {
            acc.add(cosThetaH, sinThetaH, fullPhiCos[i], weight * fullPhiWeight[i]);
        }
    });
    // φ ∈ [0, φmax]: n·l falls linearly to 0 at φmax, and V varies over n·l ~ α there. With
    // φ = φmax (1 − t²) the nodes crowd towards φmax (n·l ∝ t²) and the integrand is smooth in t.
    outer(sFull, sEnd, [&](double cosThetaH, double sinThetaH, double weight) {
        const double cosTheta2H = 2.0 * cosThetaH * cosThetaH - 1.0;
        const double sinTheta2H = 2.0 * sinThetaH * cosThetaH;
        const double c = -(NoV * cosTheta2H) / (acc.sinThetaV * sinTheta2H);
        const double phiMax = std::acos(std::clamp(c, -1.0, 1.0));
        if (!(phiMax > 0.0)) return;
        forEachNode(0.0, 1.0, kPartialPhiPanels * refinement, [&](double t, double wt) {
            const double phi = phiMax * (1.0 - t * t);
            acc.add(cosThetaH, sinThetaH, std::cos(phi), weight * wt * 2.0 * phiMax * t);
        });
    });
    return {acc.a, acc.b};
}

SplitSum splitSum(double NoV, double roughness) { return splitSumRefined(NoV, roughness, 1); }

double directionalAlbedo(double NoV, double roughness) {
    const SplitSum s = splitSum(NoV, roughness);
    return s.a + s.b;
}

// ---- Environment geometry ----

glm::dvec3 texelDirection(uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
    const double phi = ((x + 0.5) / width - 0.5) * 2.0 * std::numbers::pi;
    const double theta = (y + 0.5) / height * std::numbers::pi;
    const double s = std::sin(theta);
    return {s * std::cos(phi), std::cos(theta), s * std::sin(phi)};
}

double texelSolidAngle(uint32_t y, uint32_t width, uint32_t height) {
    const double theta0 = std::numbers::pi * y / height, theta1 = std::numbers::pi * (y + 1.0) / height;
    return 2.0 * std::numbers::pi / width * (std::cos(theta0) - std::cos(theta1));
}

namespace {

// The texel-centre directions of a map, as per-column (cos φ, sin φ) and per-row (cos θ, sin θ)
// tables plus each row's solid angle per texel and polar band [θ0, θ1].
struct Grid {
    std::vector<double> cosPhi, sinPhi, cosTheta, sinTheta, solidAngle, theta0, theta1;

    explicit Grid(const assets::Environment& env) {
        const uint32_t w = env.width, h = env.height;
        cosPhi.resize(w);
        sinPhi.resize(w);
        for (uint32_t x = 0; x < w; ++x) {
            const double phi = ((x + 0.5) / w - 0.5) * 2.0 * std::numbers::pi;
            cosPhi[x] = std::cos(phi);
            sinPhi[x] = std::sin(phi);
        }
        for (uint32_t y = 0; y < h; ++y) {
            const double theta = (y + 0.5) / h * std::numbers::pi;
            cosTheta.push_back(std::cos(theta));
            sinTheta.push_back(std::sin(theta));
            solidAngle.push_back(texelSolidAngle(y, w, h));
            theta0.push_back(std::numbers::pi * y / h);
            theta1.push_back(std::numbers::pi * (y + 1.0) / h);
        }
    }

    glm::dvec3 direction(uint32_t x, uint32_t y) const {
        return {sinTheta[y] * cosPhi[x], cosTheta[y], sinTheta[y] * sinPhi[x]};
    }

    // True when every direction of row y is at least 90° (plus a margin) from unit `n`, i.e. has
    // n·l < 0: the angular distance from n to the band [θ0, θ1] is max(0, θ0 − θn, θn − θ1).
    bool rowBelowHorizon(uint32_t y, double thetaN) const {
        return std::max({0.0, theta0[y] - thetaN, thetaN - theta1[y]}) > 0.5 * std::numbers::pi + 1e-9;
    }
};

glm::dvec3 texelValue(const assets::Environment& env, uint32_t x, uint32_t y) {
    const float* t = env.texel(x, y);
    return {double(t[0]), double(t[1]), double(t[2])};
}

// Σ L(l)·weight(n·l, l) Ω / Σ weight(n·l, l) Ω over the texels with n·l > 0.
template <class Weight>
glm::dvec3 weightedAverage(const assets::Environment& env, const glm::dvec3& n, Weight&& weight) {
    const Grid grid(env);
    const double thetaN = std::acos(std::clamp(n.y, -1.0, 1.0));
    glm::dvec3 sum(0.0);
    double total = 0.0;
    for (uint32_t y = 0; y < env.height; ++y) {
        if (grid.rowBelowHorizon(y, thetaN)) continue;
        const double omega = grid.solidAngle[y];
        for (uint32_t x = 0; x < env.width; ++x) {
            const double NoL = glm::dot(n, grid.direction(x, y));
            if (NoL <= 0.0) continue;
            const double w = weight(NoL) * omega;
            sum += w * texelValue(env, x, y);
            total += w;
        }
    }
    return total > 0.0 ? sum / total : glm::dvec3(0.0);
}

}  // namespace

// ---- Environment integrals ----

glm::dvec3 bilinear(const assets::Environment& env, const glm::dvec3& direction) {
    const glm::dvec3 d = glm::normalize(direction);
    const double phi = (d.x == 0.0 && d.z == 0.0) ? 0.0 : std::atan2(d.z, d.x);
    const double u = 0.5 + phi / (2.0 * std::numbers::pi);
    const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;

    const auto split = [](double t, double& index, double& fraction) {
        index = std::floor(t);
        fraction = t - index;
        if (fraction < kSnap) fraction = 0.0;
        if (fraction > 1.0 - kSnap) {
            index += 1.0;
            fraction = 0.0;
        }
    };
    double xIndex = 0.0, fx = 0.0, yIndex = 0.0, fy = 0.0;
    split(u * env.width - 0.5, xIndex, fx);
    split(std::clamp(v * env.height - 0.5, 0.0, double(env.height - 1)), yIndex, fy);
    const int64_t w = env.width;
    const uint32_t x0 = uint32_t(((int64_t(xIndex) % w) + w) % w);
    const uint32_t x1 = uint32_t((x0 + 1) % w);
    const uint32_t y0 = std::min(uint32_t(yIndex), env.height - 1);
    const uint32_t y1 = std::min(y0 + 1, env.height - 1);
    // With fx = fy = 0 this is exactly texel (x0, y0) (texels are finite).
    const glm::dvec3 top = texelValue(env, x0, y0) * (1.0 - fx) + texelValue(env, x1, y0) * fx;
    const glm::dvec3 bottom = texelValue(env, x0, y1) * (1.0 - fx) + texelValue(env, x1, y1) * fx;
    return top * (1.0 - fy) + bottom * fy;
}

glm::dvec3 prefiltered(const assets::Environment& env, const glm::dvec3& R, double roughness) {
    roughness = std::clamp(roughness, 0.0, 1.0);
    const double alpha = roughness * roughness;
    if (2.0 * alpha < std::numbers::pi / env.height) return bilinear(env, R);
    const glm::dvec3 n = glm::normalize(R);
    const double alpha2 = alpha * alpha;
    // With n = v, h = normalize(n + l) has (n·h)² = (1 + n·l)/2, so
    // (n·h)²(α² − 1) + 1 = (α² (1 + n·l) + (1 − n·l)) / 2.
    return weightedAverage(env, n, [alpha2](double NoL) {
        const double d = alpha2 * (1.0 + NoL) + (1.0 - NoL);
        return 4.0 * alpha2 / (std::numbers::pi * d * d) * NoL;
    });
}

glm::dvec3 irradiance(const assets::Environment& env, const glm::dvec3& n) {
    return weightedAverage(env, glm::normalize(n), [](double NoL) { return NoL; });
}

// ---- Spherical harmonics ----

std::array<double, 9> shBasis(const glm::dvec3& d) {
    const double c0 = std::sqrt(1.0 / (4.0 * std::numbers::pi));
    const double c1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
    const double c2 = std::sqrt(15.0 / (4.0 * std::numbers::pi));
    const double c20 = std::sqrt(5.0 / (16.0 * std::numbers::pi));
    const double c22 = std::sqrt(15.0 / (16.0 * std::numbers::pi));
    return {c0,
            c1 * d.y,
            c1 * d.z,
            c1 * d.x,
            c2 * d.x * d.y,
            c2 * d.y * d.z,
            c20 * (3.0 * d.z * d.z - 1.0),
            c2 * d.x * d.z,
            c22 * (d.x * d.x - d.y * d.y)};
}

Sh9 projectSh9(const assets::Environment& env) {
    const Grid grid(env);
    Sh9 sh{};
    for (uint32_t y = 0; y < env.height; ++y) {
        const double omega = grid.solidAngle[y];
        for (uint32_t x = 0; x < env.width; ++x) {
            const std::array<double, 9> basis = shBasis(grid.direction(x, y));
            const glm::dvec3 L = texelValue(env, x, y) * omega;
            for (size_t i = 0; i < 9; ++i) sh[i] += L * basis[i];
        }
    }
    return sh;
}

glm::dvec3 irradianceFromSh9(const Sh9& sh, const glm::dvec3& n) {
    // Â_l / π: 1, 2/3, 1/4.
    constexpr std::array<double, 9> kBand = {1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};
    const std::array<double, 9> basis = shBasis(n);
    glm::dvec3 e(0.0);
    for (size_t i = 0; i < 9; ++i) e += sh[i] * (kBand[i] * basis[i]);
    return e;
}

// ---- Test environments ----

assets::Environment makeEnvironment(uint32_t width, uint32_t height,
                                   const std::function<glm::dvec3(const glm::dvec3& direction)>& radiance) {
    assets::Environment env;
    env.source = "reference";
    env.width = width;
    env.height = height;
    env.rgb.resize(env.texelCount() * 3);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const glm::dvec3 L = radiance(texelDirection(x, y, width, height));
            float* t = env.texel(x, y);
            t[0] = float(L.x);
            t[1] = float(L.y);
            t[2] = float(L.z);
        }
    }
    return env;
}

}  // namespace candela::reports::reference
