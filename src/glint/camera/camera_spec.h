// The view as a scene describes it: the notes' view-reference model (look-from, look-at, up),
// a projection, a thin lens and a shutter.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "glint/math/vector.h"

namespace glint {

// How film positions become eye rays. Beside the pinhole's perspective and the orthographic
// view, the wide projections of POV-Ray (Camera::generate_ray has their formulas): each turns
// the film's axes into angles, so that a view can span up to a full turn.
enum class Projection {
    perspective,
    orthographic,
    fisheye,           // equidistant: the angle from the view axis grows with the distance from
                       // the centre; nothing is seen outside the circle the view's height spans
    ultra_wide_angle,  // the film's x and y both angles, as latitude and longitude of a kind
    panoramic,         // half a turn across, the vertical as a perspective camera's tangent
    cylindrical,       // an angle round an axis one way, straight (or parallel) along it
    spherical,         // equirectangular: longitude across, latitude up
};

inline constexpr Projection kProjections[] = {Projection::perspective, Projection::orthographic,
                                              Projection::fisheye,     Projection::ultra_wide_angle,
                                              Projection::panoramic,   Projection::cylindrical,
                                              Projection::spherical};

// The projection's name as scene files write it ("ultra_wide_angle").
constexpr const char* projection_name(Projection p) {
    switch (p) {
        case Projection::perspective:
            return "perspective";
        case Projection::orthographic:
            return "orthographic";
        case Projection::fisheye:
            return "fisheye";
        case Projection::ultra_wide_angle:
            return "ultra_wide_angle";
        case Projection::panoramic:
            return "panoramic";
        case Projection::cylindrical:
            return "cylindrical";
        case Projection::spherical:
            return "spherical";
    }
    return "?";
}

// The camera named in a sentence: "an orthographic camera", "a fisheye camera".
inline std::string camera_named(Projection p) {
    const std::string name = projection_name(p);
    const bool vowel = std::string_view("aeiou").find(name[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + name + " camera";
}

// A thin lens (Potmesil and Chakravarty 1981, as Cook, Porter and Carpenter 1984 trace it): each
// eye ray starts at a point of the aperture and passes through the point of the plane of focus
// that the pinhole ray through the same film position meets. Points on that plane stay sharp;
// others blur into the image of the aperture.
struct LensSpec {
    float radius = 0;          // of the aperture, in scene units; 0 is a pinhole: all in focus
    float focus_distance = 0;  // from the eye along the view direction; 0: |at - from|
    int blades = 0;            // 0: a round aperture; 3 or more: a regular polygon of as many
    float blade_rotation = 0;  // degrees, turning the polygon about the view direction
};

// Where the camera is at one moment of a moving camera's path.
struct CameraKeyframe {
    float time;
    Point3 from, at;
    Vector3 up;
};

struct CameraSpec {
    Projection projection = Projection::perspective;
    Point3 from{0, 0, 0};  // the eye
    Point3 at{0, 0, 1};    // the point at the image centre; != from
    Vector3 up{0, 1, 0};   // need not be perpendicular to the view; not parallel to it
    // Degrees: for perspective the full vertical field of view, in (0, 180); in (0, 360] the
    // fisheye's across the circle, ultra_wide_angle's and spherical's across the view's width,
    // cylindrical's round its axis.
    float fov = 45;
    float vertical_fov = 180;  // spherical: degrees of latitude across the height, in (0, 180]
    // orthographic: height of the view in scene units, > 0; cylindrical: the view's extent along
    // the axis, at distance 1 (or in scene units when it looks parallel along it).
    float height = 2;
    // cylindrical: the axis lies along the view's width (else its height), and rays are parallel
    // along it (else they spread as a perspective camera's).
    bool cylinder_axis_across = false, cylinder_parallel = false;
    // The view's width over its height: 0 for the image's own (square pixels), or as POV-Ray's
    // right and up vectors give it, which stretch the view over the image whatever its size.
    float aspect = 0;
    LensSpec lens;
    // The shutter is open from shutter_open to shutter_close: eye rays take times spread over
    // it, which blurs what moves. Equal times freeze the picture at that moment.
    float shutter_open = 0, shutter_close = 0;
    // A moving camera: from, at and up at increasing times (from moves in a line, the view turns
    // by quaternion interpolation). Empty: the camera stands still at from, at, up.
    std::vector<CameraKeyframe> motion;
    // Right is up x forward rather than forward x up: the image a left-handed system sees, as
    // POV-Ray's cameras do, so that its scenes keep their coordinates.
    bool left_handed = false;
};

}  // namespace glint
