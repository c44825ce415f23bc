// glint's own POV-Ray test scene for normal patterns: the slope of gradient, onion, radial,
// leopard and marble patterns (with bump_size, frequency and accuracy), of a pigment's grey
// (pigment_pattern, bricks), a declared normal in a texture, shallow bumps and waves, all placed
// by their objects' transforms. Its reference,
// normals-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Inormals.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 5, -6> color rgb 0.4 }
#declare Ridges = normal { gradient x 0.8 scale 0.4 }
plane { y, 0 pigment { color rgb 0.8 } normal { leopard 0.6 scale 0.15 rotate y*30 } }
sphere { <-2.4, 1, 0>, 1 texture { pigment { color rgb <0.9, 0.5, 0.3> } normal { Ridges rotate z*30 } finish { phong 0.6 } } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.4, 0.6, 0.9> } normal { onion bump_size 1.2 frequency 2 scale 0.5 } finish { phong 0.8 phong_size 60 } translate <0, 0, 0.5> }
union {
  box { <-0.9, 0, -0.9> <0.9, 1.8, 0.9> }
  pigment { color rgb 0.9 } normal { radial 0.6 frequency 8 accuracy 0.01 }
  rotate y*30 translate <2.4, 0, 0>
}
sphere { <-1.2, 0.5, -2>, 0.5 pigment { color rgb <0.9, 0.9, 0.5> } normal { marble 0.8 scale 0.2 rotate y*40 } finish { specular 0.5 roughness 0.02 } }
sphere { <1.2, 0.5, -2>, 0.5 pigment { color rgb <0.6, 0.9, 0.6> } normal { bumps 0.15 scale 0.5 } scale <1.2, 1, 1> }
box { <-0.6, 0, -0.1> <0.6, 0.8, 0.1> pigment { color rgb 0.85 } normal { pigment_pattern { brick color rgb 1 color rgb 0.2 scale 0.05 } 0.6 } finish { phong 0.5 } rotate y * -20 translate <0, 0, -3> }
