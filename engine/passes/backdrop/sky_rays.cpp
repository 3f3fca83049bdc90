#include "passes/backdrop/sky_rays.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace candela::passes {

shading::SkyRays skyRays(const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec2& rotation, uint32_t width,
                         uint32_t height) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProjection));
    const glm::dvec3 from(eye);
    // The near plane's point through ndc (x, y) is inverse · (x, y, 1, 1) = c0·x + c1·y + (c2 + c3),
    // homogeneous; its direction from the eye, (xyz − eye·w)·sign(w), is linear in x and y too.
    const auto fromEye = [&](const glm::dvec4& h) { return glm::dvec3(h) - from * h.w; };
    const glm::dvec4 constant = inverse[2] + inverse[3];
    const double sign = constant.w < 0.0 ? -1.0 : 1.0;  // w at the target's centre (ndc 0, 0)
    // ndc = p · 2 / size − 1 for the pixel position p.
    const glm::dvec3 perNdcX = fromEye(inverse[0]) * sign, perNdcY = fromEye(inverse[1]) * sign;
    glm::dvec3 perX = perNdcX * (2.0 / width), perY = perNdcY * (2.0 / height);
    glm::dvec3 origin = fromEye(constant) * sign - perNdcX - perNdcY;
    // The environment's rotation (iblLookupDirection) is linear too; then the ray through the
    // centre gets length 1.
    const auto rotate = [&](const glm::dvec3& d) {
        return glm::dvec3(d.x * rotation.x + d.z * rotation.y, d.y, -d.x * rotation.y + d.z * rotation.x);
    };
    perX = rotate(perX), perY = rotate(perY), origin = rotate(origin);
    const double centre = glm::length(perX * (width / 2.0) + perY * (height / 2.0) + origin);
    const double scale = centre > 0.0 && std::isfinite(centre) ? 1.0 / centre : 1.0;
    return {.perX = glm::vec4(glm::vec3(perX * scale), 0.0f),
            .perY = glm::vec4(glm::vec3(perY * scale), 0.0f),
            .origin = glm::vec4(glm::vec3(origin * scale), 0.0f)};
}

}  // namespace candela::passes
