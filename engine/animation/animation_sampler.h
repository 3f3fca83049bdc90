#pragma once
// glTF 2.0 animation samplers on the CPU: validation and evaluation of STEP, LINEAR and
// CUBICSPLINE keyframes at a time in seconds (glTF 2.0 §3.11 and Appendix C). Pure: no scene, no
// Vulkan; the loader builds AnimationSamplers from accessors and the animation system evaluates
// them each frame.
//
//   AnimationSampler s{.times = {0, 1}, .values = {0, 0, 0, 1, 2, 3}, .width = 3};  // a translation
//   float t[3];
//   evaluateSampler(s, AnimatedProperty::Translation, 0.5, t);                        // {0.5, 1, 1.5}

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::animation {

enum class Interpolation : uint8_t { Step, Linear, CubicSpline };

// What a channel animates. Rotations are unit quaternions stored (x, y, z, w), as in glTF;
// weights are the morph-target weights of a mesh, `width` of them per key; Weight is one of them
// (KHR_animation_pointer's /nodes/{}/weights/{}). Visibility is KHR_node_visibility's bool, one
// value per key (0: hidden, anything else: visible), STEP only. Values are `width` (1 to 4) plain
// floats of any other property KHR_animation_pointer names (material factors, texture transforms,
// light and camera parameters): interpolated per component, never normalized.
enum class AnimatedProperty : uint8_t { Translation, Rotation, Scale, Weights, Weight, Visibility, Values };

// One sampler: key times in seconds and their values, `width` floats per value (3 for translation
// and scale, 4 for rotation, the morph-target count for weights, 1 for a weight or a visibility,
// the property's for Values). For CubicSpline every key holds three values in a row — in-tangent,
// value, out-tangent — so values has 3 × width floats per key.
struct AnimationSampler {
    std::vector<float> times;
    std::vector<float> values;
    Interpolation interpolation = Interpolation::Linear;
    uint32_t width = 0;
};

// Why `sampler` cannot animate `property`, as a phrase for an error message ("" when it can): no
// keys, a width that is not the property's (3 translation/scale, 4 rotation, ≥ 1 weights, 1 weight
// and visibility, 1 to 4 values), an interpolation other than STEP for a visibility, a time
// that is not finite or smaller than the one before, a value count that does not match the keys and
// the interpolation, a value that is not finite. Two keys at the same time are accepted (a jump at
// that time; exporters write them for cuts).
std::string samplerProblem(const AnimationSampler& sampler, AnimatedProperty property);

// The sampler's value at `time` (seconds, double so hours of playback keep their precision), into
// `out` (sampler.width floats). Before the first key it is the first value, after the last key the
// last value. Linear rotations are interpolated along the shorter arc (slerp); every rotation is
// normalized after interpolation (cubic splines overshoot). At two keys with the same time the later
// one holds from that time on. Precondition: samplerProblem(sampler, property) is empty and
// out.size() == sampler.width.
void evaluateSampler(const AnimationSampler& sampler, AnimatedProperty property, double time, std::span<float> out);

// `time` wrapped into [0, duration) for looping playback, computed in double (fmod), so the phase
// after 10⁶ s is as exact as after one. 0 for a duration ≤ 0 or a non-finite time.
double loopTime(double time, double duration);

}  // namespace candela::animation
