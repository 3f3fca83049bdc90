#pragma once
// Framing: where the orbit camera stands and how wide it looks when the command line leaves that to
// Candela (docs/scenes.md, "Framing"). It fits the points of what is shown — the vertices in world
// space, as placed, skinned and morphed (pose/shown_points.h) — not a box around them, so a file
// restructured without changing its image frames the same.
//
//   target      the centre of the points' bounding box;
//   distance    R / sin 15°, R the largest distance from the target to a point: the sphere of
//               radius R about the target just fills a 30° cone (kFramingConeDegrees). This is
//               model-viewer's rule for its ideal camera distance, at its default 30° field of view
//               (it then stands at 105% of it). The eye is 3.9 R from the target, so perspective
//               stays modest whatever the direction: a product shot, not a wide angle;
//   field of view  the narrowest vertical one in which every point's projection lies within the
//               central kSilhouetteSpan (80%) of the image's width and of its height: a margin of
//               at least 10% of the image on each side of the projected silhouette, exactly 10% on
//               the side that limits it. model-viewer keeps 30° (wider for narrow images) and leaves
//               its margin to the sphere, so a model much smaller than its sphere (a long one seen
//               end-on) comes out small there.
// Framed from several directions (a turntable, views) the distance is the same for each and the
// field of view the widest any of them needs, so that every frame keeps the margin. A given field of
// view (--fov) replaces the fitted one at the same distance.

#include "scene/camera.h"

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace candela::scene {

// The share of the image's width and of its height the framed silhouette may span.
constexpr float kSilhouetteSpan = 0.8f;
// The cone the bounding sphere fills from the framed distance (model-viewer's default field of view).
constexpr float kFramingConeDegrees = 30.0f;

// Receives a batch of world-space points.
using PointBatch = std::function<void(std::span<const glm::vec3>)>;
// Gives the points framing fits, batch by batch, to the visitor it is called with. Framing calls it
// three times; each call must give the same points.
using PointSource = std::function<void(const PointBatch&)>;

struct FramingRequest {
    float aspect = 1.0f;                 // width / height
    std::vector<glm::vec2> directions;   // (θ°, φ°) of each view; at least one
    std::optional<float> fovYDegrees;    // given: kept at the framed distance; none: fitted
};

// The orbit camera framing the points from request.directions[0] (see the top of this file). No
// points: the default OrbitCamera looking at the origin from that direction, at 45°. A silhouette
// with no extent (one point, a segment end-on): the cone's 30°.
OrbitCamera frame(const PointSource& points, const FramingRequest& request);

// A PointSource over a fixed list of points (tests, callers that hold the points).
PointSource pointsOf(std::vector<glm::vec3> points);

}  // namespace candela::scene
