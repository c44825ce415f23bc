// Layered textures: grid lines of a colour map that is clear between them, laid over a floor
// with a finish of its own; stripes whose transmit varies over a gradient, over a checker; a
// declared layered texture changed by a pigment on top. Written for POV-Ray 3.6 with
// assumed_gamma 2.2: the colours are lit as written and the result decoded with 2.2. The view
// of right 1.6 by up 1 is stretched over the 4:3 image.
#version 3.6;
global_settings { assumed_gamma 2.2 }

camera {
  location <0, 4, -9>
  look_at <0, 0.8, 0>
  right 1.6*x
  angle 50
}
light_source { <-12, 20, -18> color rgb 1 }
light_source { <10, 8, -10> color rgb 0.4 }
background { color rgb <0.3, 0.35, 0.5> }

#macro Lines(Half)
  pigment {
    gradient x
    color_map {
      [0.0 rgbt <0.1, 0.1, 0.3, 0>]
      [Half rgbt <0.1, 0.1, 0.3, 0>]
      [Half rgbt 1]
      [1 - Half rgbt 1]
      [1 - Half rgbt <0.1, 0.1, 0.3, 0>]
      [1.0 rgbt <0.1, 0.1, 0.3, 0>]
    }
  }
#end

plane {
  y, 0
  texture { pigment { color rgb <0.9, 0.85, 0.7> } finish { ambient 0.35 diffuse 0.8 } }
  texture { Lines(0.04) }
  texture { Lines(0.04) rotate y*90 }
}

#declare Stripes =
  texture { pigment { checker color rgb <0.8, 0.2, 0.1> color rgb <0.9, 0.9, 0.8> scale 0.5 } }
  texture {
    pigment {
      gradient y
      color_map { [0 rgbf <0.1, 0.5, 0.2, 1>] [1 rgbf <0.1, 0.5, 0.2, 0>] }
      scale 3
    }
    finish { phong 0.6 phong_size 30 }
  }

box { <-3.2, 0, -0.4>, <-1.2, 3, 0.6> texture { Stripes } rotate y*20 }
sphere { <1.2, 1.2, 0>, 1.2 texture { Stripes } }
sphere { <3.3, 0.7, -1>, 0.7 texture { Stripes } pigment { rgbt <0.9, 0.6, 0.1, 0.5> } }
