// glint's own POV-Ray test scene for meshes: a mesh of triangles and smooth_triangles (a
// pyramid and a smooth-shaded dome band), declared and placed twice with object { }. Its
// reference, mesh-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Imesh.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } }
#declare Pyramid = mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> }
  triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }
}
#declare Band = mesh {
  #for (I, 0, 11)
    #declare A0 = I * 30; #declare A1 = (I + 1) * 30;
    #declare P0 = vrotate(<1, 0, 0>, y * A0); #declare P1 = vrotate(<1, 0, 0>, y * A1);
    #declare Q0 = vrotate(<0.6, 0.8, 0>, y * A0); #declare Q1 = vrotate(<0.6, 0.8, 0>, y * A1);
    smooth_triangle { P0, P0, P1, P1, Q0, Q0 }
    smooth_triangle { P1, P1, Q1, Q1, Q0, Q0 }
  #end
}
object { Pyramid pigment { rgb <0.9, 0.5, 0.2> } translate <-2, 0, 0> }
object { Pyramid pigment { rgb <0.3, 0.6, 0.9> } rotate y * 30 scale 0.7 translate <0, 0, 2> }
object { Band pigment { rgb <0.4, 0.8, 0.4> } finish { phong 0.6 } translate <2, 0, 0> }
