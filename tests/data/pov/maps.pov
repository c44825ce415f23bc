// Pigment maps (with a nested pattern, a list pattern of pigments and an average), POV-Ray's
// mandel and spiral patterns, a sky of a pigment map, an unbounded paraboloid, and an
// orthographic camera sized by its angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  orthographic
  location <0, 4, -10>
  look_at <0, 1, 0>
  angle 40
}
light_source { <-20, 30, -30> color rgb 1 }

sky_sphere {
  pigment {
    gradient y
    pigment_map {
      [0.0 color rgb <0.9, 0.8, 0.7>]
      [0.3 gradient x color_map { [0 rgb <0.2, 0.3, 0.8>] [1 rgb <0.6, 0.7, 1.0>] } scale 0.5]
    }
  }
}

plane {
  y, 0
  pigment {
    checker
      pigment { gradient x color_map { [0 rgb <0.8, 0.2, 0.2>] [1 rgb <0.9, 0.9, 0.2>] } }
      pigment { rgb <0.2, 0.4, 0.3> }
    scale 1.5
  }
  finish { ambient 0.2 diffuse 0.8 }
}

sphere {
  <-3, 1, 0>, 1
  pigment {
    gradient y
    pigment_map {
      [0.2 rgb <0.1, 0.2, 0.9>]
      [0.5 onion color_map { [0 rgb 1] [1 rgb <0.9, 0.5, 0.1>] } scale 0.2]
      [0.8 rgb <0.9, 0.1, 0.1>]
    }
    scale 2 translate -y
  }
  finish { ambient 0.2 diffuse 0.8 }
}

box {
  <-0.9, 0, -0.9>, <0.9, 1.8, 0.9>
  pigment {
    mandel 30
    color_map { [0 rgb <0, 0, 0.4>] [0.5 rgb <0.9, 0.9, 1>] [1 rgb 0] }
    scale 0.6 translate <-0.4, 0.9, 0>
  }
  finish { ambient 0.5 diffuse 0.5 }
}

sphere {
  <3, 1, 0>, 1
  pigment {
    average
    pigment_map {
      [1 spiral1 3 color_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.1, 0.5, 0.1>] } rotate 90*x scale 0.5]
      [2 spiral2 5 color_map { [0 rgb <0.2, 0.2, 0.9>] [1 rgb 1] } rotate 90*x]
    }
    translate <3, 1, 0>
  }
  finish { ambient 0.2 diffuse 0.8 }
}

// shapes_old.inc's Paraboloid_Y: unbounded, cut only by the scene's far box in glint.
quadric {
  <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0
  pigment { rgb <0.7, 0.5, 0.9> }
  scale <0.5, 2, 0.5> rotate 180*x translate <0, 3.6, 2.5>
}
