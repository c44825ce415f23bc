// The distributed-ray-tracing benchmark scene for POV-Ray 3.7: scene.yaml, written so that POV-Ray
// renders it as glint does (the conventions of bench/spd_vs_povray/nff2pov.py). run.py sets the
// sampling from the command line, e.g.
//   povray +Iscene.pov +Oout.exr +FE +W480 +H270 -A -D Declare=BlurSamples=64 Declare=AreaN=4
#version 3.7;

// Samples. Each pixel takes BlurSamples eye rays (focal blur; they also spread over the pixel,
// so anti-aliasing stays off), and every shadow test of the area light takes AreaN x AreaN rays
// (AreaN >= 2; powers of 2, which POV-Ray's recursive average weighs evenly).
#ifndef (BlurSamples) #declare BlurSamples = 64; #end
#ifndef (AreaN) #declare AreaN = 4; #end
// -1: every point of the AreaN x AreaN grid is tested (POV-Ray's default); 0, 1, ...: POV-Ray's
// adaptive area light (the corners first, subdivided where they disagree).
#ifndef (Adaptive) #declare Adaptive = -1; #end
// 0: always BlurSamples rays a pixel; above 0, POV-Ray stops a pixel early once the variance of
// its samples is below this (with the confidence below), its adaptive focal blur.
#ifndef (BlurVariance) #declare BlurVariance = 0; #end
// on: the diffuse and highlight terms are computed for each point of the area light, as glint
// does; off: towards its centre only, scaled by the share of unblocked shadow rays.
#ifndef (AreaIllumination) #declare AreaIllumination = on; #end

// Linear colours as glint's; the ray tree cut at depth 5 (the eye ray is level 1 in both), with
// no cut-off by weight (glint: min_weight 0).
global_settings {
  assumed_gamma 1
  max_trace_level 5
  adc_bailout 0
  ambient_light rgb <0.2, 0.2, 0.22>
}
background { rgb <0.5, 0.62, 0.8> }

// The camera, built from glint's from, at, up and vertical fov as glint builds it (right-handed:
// right = direction x up), with explicit vectors, which POV-Ray takes as given.
#declare From = <0, 2.3, -8.5>;
#declare At = <0, 0.9, 0>;
#declare Sky = <0, 1, 0>;
#declare Fov = 38;
#declare LensRadius = 0.12;
#declare FocusDistance = 8.0;
#declare H = 2 * tan(radians(Fov / 2));
#declare Aspect = image_width / image_height;
// Mirror = 1 renders the image mirrored left to right (run.py flips it back): POV-Ray draws a
// pixel's sub-pixel positions from its coordinates, so the mirrored reference shares none with
// the sweep's images, whose errors it would otherwise understate.
#ifndef (Mirror) #declare Mirror = 0; #end
#declare Flip = (Mirror ? -1 : 1);
#declare Dir0 = vnormalize(At - From);
#declare Right0 = vnormalize(vcross(Dir0, Sky));
#declare Up0 = vcross(Right0, Dir0);
// POV-Ray's focal blur moves every sample 1/32 pixel left and up: it adds (j - 0.5) / 16 to
// the sub-pixel position with j in [-0.5, 0.5] (backend/render/tracepixel.cpp). The camera
// turns by as much the other way, so that the two images line up.
#declare Dir = vnormalize(Dir0 + Flip * Right0 * H * Aspect / (32 * image_width)
                               - Up0 * H / (32 * image_height));
#declare Right = vnormalize(vcross(Dir, Sky));
#declare Up = vcross(Right, Dir);
camera {
  perspective
  location From
  direction Dir
  right Flip * Right * H * Aspect
  up Up * H
  // POV-Ray draws lens points in a disc of radius aperture / 4 (r = aperture / 2 times a
  // sample grid of radius 0.5, backend/render/tracepixel.cpp).
  aperture 4 * LensRadius
  blur_samples BlurSamples
  confidence 0.9
  variance BlurVariance
  // The plane of focus is perpendicular to the view at the focal point's distance, as glint's.
  focal_point From + FocusDistance * Dir0
}

// The area light. POV-Ray puts its AreaN points at the ends and AreaN - 2 evenly between, and
// jitter moves each by up to half the spacing: with sides (AreaN - 1) / AreaN of glint's, the
// jittered points cover glint's rectangle exactly, one stratum each, whatever AreaN is. Its
// colour is shared among the points, as glint's area light's is averaged over them.
#declare LightScale = (AreaN - 1) / AreaN;
light_source {
  <-4, 7, -4>
  color rgb <0.85, 0.83, 0.78>
  area_light <2.5, 0, 0> * LightScale, <0, 0, 2.5> * LightScale, AreaN, AreaN
  jitter
  #if (Adaptive >= 0) adaptive Adaptive #end
  area_illumination AreaIllumination
}
light_source { <5, 4, -3> color rgb <0.3, 0.32, 0.38> }

// glint's Phong model: ka C Ia + kd C (N.L) IL + ks (R.V)^n IL + kr I(reflected). POV-Ray's
// phong is (R.V)^phong_size in the light's colour, its reflection uncoloured, as glint's.
#macro GlintFinish(Ka, Kd, Ks, Shininess, Kr)
  finish {
    ambient Ka diffuse Kd
    #if (Ks > 0) phong Ks phong_size Shininess #end
    #if (Kr > 0) reflection Kr #end
  }
#end

// glint's solid checker: even squares (floor x + floor y + floor z even) the first colour.
// POV-Ray's checker takes floor(x + 0.001) (and so for y and z, so that a plane at y = 0 stays
// on one side): moved by 0.001 in x and z, its squares are glint's.
plane {
  <0, 1, 0>, 0
  texture {
    pigment { checker rgb <0.9, 0.88, 0.84>, rgb <0.3, 0.3, 0.35> translate <0.001, 0, 0.001> }
    GlintFinish(0.45, 0.6, 0, 0, 0.15)
  }
}
sphere { <-2.9, 1, 1.2>, 1
  texture { pigment { rgb <0.95, 0.68, 0.22> } GlintFinish(0.3, 0.6, 0.6, 60, 0.3) } }
sphere { <-0.6, 1.1, 2.6>, 1.1
  texture { pigment { rgb <0.95, 0.95, 0.97> } GlintFinish(0.05, 0.05, 0.8, 300, 0.85) } }
sphere { <0.4, 0.85, -0.6>, 0.85
  texture { pigment { rgb <0.85, 0.12, 0.1> } GlintFinish(0.35, 0.7, 0.5, 60, 0) } }
sphere { <2.3, 0.8, 0.6>, 0.8
  texture { pigment { rgb <0.15, 0.3, 0.8> } GlintFinish(0.35, 0.7, 0.4, 40, 0.1) } }
sphere { <-1.4, 0.45, -2.6>, 0.45
  texture { pigment { rgb <0.9, 0.9, 0.9> } GlintFinish(0.35, 0.7, 0.5, 80, 0) } }
sphere { <1.6, 0.35, -3.2>, 0.35
  texture { pigment { rgb <0.2, 0.7, 0.25> } GlintFinish(0.35, 0.7, 0.5, 60, 0) } }
