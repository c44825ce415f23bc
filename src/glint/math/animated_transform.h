// Keyframed transforms for motion blur. Each keyframe splits into translation, rotation and
// stretch, which interpolate apart (Shoemake and Duff 1992, as pbrt's AnimatedTransform does),
// and a moving box is bounded over a time interval for the acceleration structures.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glint/math/bounds.h"
#include "glint/math/quaternion.h"
#include "glint/math/transform.h"

namespace glint {

// An affine matrix as translate(translation) * rotation_matrix(rotation) * stretch.
struct Decomposed {
    Vector3 translation;
    Quaternion rotation;  // unit, a proper rotation: a mirror lives in the stretch
    // Symmetric upper 3x3 (scales and shears), no translation. Positive definite, or negative
    // definite when the matrix mirrors (determinant < 0).
    Matrix4 stretch;
};

// Polar decomposition of the upper 3x3 A = R S (Shoemake and Duff 1992) by Newton's iteration
// Q <- (g Q + Q^-T / g) / 2 with Higham's (1986) scaling g, bounded in iterations; the
// orthogonal limit Q is negated when det A < 0 so that R is a rotation and S = R^T A.
// Nothing when the matrix is not affine (bottom row other than 0 0 0 1), has a non-finite
// entry, or is singular (as glint::inverse judges it).
std::optional<Decomposed> decompose(const Matrix4& affine);
// translate(translation) * rotation * stretch as one matrix: decompose's inverse.
Matrix4 recompose(const Decomposed& parts);

struct Keyframe {
    float time;  // in the shutter's units; see AnimatedTransform for the order keyframes need
    Transform world_from_object;
};

// A transform that moves with time through its keyframes. Between two keyframes translation
// and stretch interpolate linearly and rotation by slerp; outside them it holds the first or
// last keyframe. Immutable after construction; at() and motion_bounds() are thread-safe.
class AnimatedTransform {
public:
    // The identity, at all times.
    AnimatedTransform();
    // `world_from_object` at all times.
    explicit AnimatedTransform(const Transform& world_from_object);
    // Throws std::invalid_argument with describe_problem's message when the keyframes are
    // invalid; loaders call describe_problem first to report the problem where it was written.
    explicit AnimatedTransform(std::vector<Keyframe> keyframes);

    // Why the keyframes cannot make an AnimatedTransform, or "" when they can. They need: at
    // least one keyframe; finite, strictly increasing times; and, when there is more than one,
    // affine non-singular transforms that all keep or all flip handedness (interpolating a mirror
    // into a non-mirror would pass through a flat, singular transform).
    static std::string describe_problem(const std::vector<Keyframe>& keyframes);

    // The transform at `time`: a keyframe's own Transform (bit for bit) at its time, on and
    // before the first and on and after the last; the interpolation in between. A NaN time
    // gives the first keyframe.
    Transform at(float time) const;

    // True when the transform is the same at all times (one keyframe, or all keyframes' transforms
    // equal).
    bool is_static() const { return static_; }
    float start_time() const { return keyframes_.front().time; }
    float end_time() const { return keyframes_.back().time; }
    const std::vector<Keyframe>& keyframes() const { return keyframes_; }

    // A world-space box that contains at(t)(p) for every p in object_bounds and every t in
    // [t0, t1] (the two are swapped if t1 < t0; a NaN bound stands for all times). Empty stays
    // empty and an unbounded box gives the whole of space. A static transform gives exactly
    // at(t0)(object_bounds). Cost: per keyframe segment in [t0, t1], two sampled boxes when the
    // orientation does not change, a few dozen for a half turn (microseconds).
    Bounds3 motion_bounds(const Bounds3& object_bounds, float t0, float t1) const;

private:
    // What motion_bounds needs to know of the motion between keyframes i and i + 1.
    struct Segment {
        bool is_static;        // both keyframes have the same transform
        float rotation_angle;  // radians in [0, pi], rounded up: the turn from i to i + 1
        float stretch_norm;    // >= the operator norm of the stretch anywhere in the segment
        float stretch_change;  // >= the operator norm of stretch(i + 1) - stretch(i)
        float translation;     // >= the length of the translation anywhere in the segment
    };

    // Keyframe i's time mapped to 0 and keyframe i + 1's to 1. Monotonic in time.
    float segment_fraction(std::size_t i, float time) const;
    // The interpolated transform at fraction u of segment i.
    Transform interpolate(std::size_t i, float u) const;
    // The box holding segment i's motion for fractions in [u0, u1], 0 <= u0 <= u1 <= 1.
    Bounds3 segment_bounds(std::size_t i, const Bounds3& object_bounds, float u0, float u1) const;

    std::vector<Keyframe> keyframes_;
    std::vector<Decomposed> parts_;  // one per keyframe when there is more than one keyframe
    std::vector<Segment> segments_;  // one per pair of consecutive keyframes
    bool static_ = true;
};

}  // namespace glint
