// Equirectangular environment mapping, shared by GLSL and C++ so the CPU loader, the procedural sky,
// the tests and the IBL shaders use one convention.
//
// Convention (the Khronos glTF Sample Viewer's at rotation 0): a unit world direction d samples
//     u = 0.5 + atan2(d.z, d.x) / 2π        v = acos(d.y) / π
// with v = 0 the top row (+Y, up) and v = 1 the bottom row (−Y). The image centre (0.5, 0.5) faces
// +X, u = 0.75 faces +Z, u = 0.25 faces −Z and the left/right edge (u = 0 ≡ 1) faces −X.
//
// Rotation θ (radians, `--env-rotation` in degrees) turns the environment about +Y exactly as the
// Sample Viewer's environmentRotation does: direction d samples the map where R·d sampled it at
// rotation 0, R being the right-handed rotation about +Y by θ (x' = x cosθ + z sinθ,
// z' = −x sinθ + z cosθ). So  u = 0.5 + (atan2(d.z, d.x) − θ) / 2π  (wrapped to [0, 1)): a positive
// θ turns the environment from +X towards +Z (clockwise seen from above, looking down −Y) — at
// θ = +90° the image centre faces +Z, and +X sees u = 0.25 (what −Z saw at θ = 0).
#ifndef CANDELA_SHARED_ENVIRONMENT_H
#define CANDELA_SHARED_ENVIRONMENT_H

#include "shared/compat.h"

CANDELA_NAMESPACE_BEGIN

#ifndef CANDELA_PI
#define CANDELA_PI 3.14159265358979f
#endif
#define CANDELA_TWO_PI 6.28318530717959f

// The equirectangular texture coordinate that unit direction `d` samples at environment rotation
// `rotation` (radians). u is in [0, 1) and v in [0, 1]. The poles (d.x = d.z = 0) give u = 0.5 − θ/2π
// (GLSL's atan(0, 0) is undefined, so it is not evaluated there).
CANDELA_FN vec2 directionToEquirectUv(vec3 d, float rotation) {
    float phi = (d.x == 0.0f && d.z == 0.0f) ? 0.0f : atan(d.z, d.x);
    float u = fract(0.5f + (phi - rotation) * (1.0f / CANDELA_TWO_PI));
    float v = acos(clamp(d.y, -1.0f, 1.0f)) * (1.0f / CANDELA_PI);
    return vec2(u, v);
}

// The inverse: the unit world direction that samples `uv` at environment rotation `rotation`.
// Any u is accepted (periodic); v is clamped to [0, 1].
CANDELA_FN vec3 equirectUvToDirection(vec2 uv, float rotation) {
    float phi = (uv.x - 0.5f) * CANDELA_TWO_PI + rotation;
    float theta = clamp(uv.y, 0.0f, 1.0f) * CANDELA_PI;
    float s = sin(theta);
    return vec3(s * cos(phi), cos(theta), s * sin(phi));
}

CANDELA_NAMESPACE_END

#endif
