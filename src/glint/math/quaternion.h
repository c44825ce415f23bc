// Unit quaternions for orientations that interpolate smoothly: conversion to and from rotation
// matrices and spherical linear interpolation (Shoemake 1985), for keyframed motion.
#pragma once

#include "glint/math/transform.h"
#include "glint/math/vector.h"

namespace glint {

// q = (v, w) = (sin(theta/2) axis, cos(theta/2)) is the right-handed rotation by theta about the
// unit axis; q and -q are the same rotation. The default is the identity.
struct Quaternion {
    Vector3 v;
    float w = 1;

    constexpr bool operator==(const Quaternion&) const = default;
};

constexpr float dot(Quaternion a, Quaternion b) { return dot(a.v, b.v) + a.w * b.w; }
// q scaled to unit length; q must not be zero.
Quaternion normalize(Quaternion q);

// The quaternion of the proper rotation in the upper 3x3 of `rotation` (orthonormal, determinant
// +1; the rest of the matrix is ignored), by Shepperd's method (1978): it divides by the largest
// of 4w^2, 4x^2, 4y^2, 4z^2, so no case loses precision. The result has unit length.
Quaternion quaternion_from_rotation(const Matrix4& rotation);

// The rotation matrix of q (no translation). q need not have unit length: it is scaled to it.
Matrix4 rotation_matrix(Quaternion q);

// The rotation angle, in radians in [0, pi], of the rotation that takes orientation a to b along
// the shorter arc. It is computed from |a - b| and |a + b|, which stay accurate when a ~ b,
// unlike acos(dot(a, b)).
float rotation_angle_between(Quaternion a, Quaternion b);

// Spherical linear interpolation from a (t = 0) to b (t = 1) at constant angular speed along the
// shorter arc: b is negated when dot(a, b) < 0, so the rotation turns by at most 180 degrees.
// When a and b are nearly equal it is the normalised linear interpolation, which then differs
// from the arc by less than float rounding. a and b are unit quaternions; the result is unit.
Quaternion slerp(Quaternion a, Quaternion b, float t);

}  // namespace glint
