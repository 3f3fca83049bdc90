#pragma once
// Double-precision quadrature over the sphere for the tests that integrate a lobe against an
// environment (anisotropy_ibl_error_test.cpp, layer_ibl_error_test.cpp).

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace candela::test {

// ∫ over the sphere of g(L) dL on a grid about `axis`: `cells` rows in θ, twice as many columns in φ.
template <class Value, class Integrand>
Value integrateSphere(const glm::dvec3& axis, int cells, Integrand&& g) {
    const glm::dvec3 z = glm::normalize(axis);
    const glm::dvec3 helper = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(helper, z)), y = glm::cross(z, x);
    // Denser near the axis: cos θ in [−1, 1] mapped as 1 − 2u², which puts half the rows within the
    // lobe's few degrees (weights by the Jacobian 4u).
    Value sum{};
    for (int i = 0; i < cells; ++i) {
        const double u = (i + 0.5) / cells;
        const double cosTheta = 1.0 - 2.0 * u * u;
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const double rowWeight = 4.0 * u / cells * (2.0 * std::numbers::pi / (2 * cells));
        for (int j = 0; j < 2 * cells; ++j) {
            const double phi = (j + 0.5) / (2 * cells) * 2.0 * std::numbers::pi;
            const glm::dvec3 l = x * (sinTheta * std::cos(phi)) + y * (sinTheta * std::sin(phi)) + z * cosTheta;
            sum += g(l) * rowWeight;
        }
    }
    return sum;
}

}  // namespace candela::test
