// glint's own POV-Ray test scene for sphere sweeps: a straight one whose radius changes, a
// B-spline one and a Catmull-Rom one, and a straight one of glass, which shows no inner
// surfaces where its pieces meet. Its reference, sweep-povray.png, is POV-Ray 3.7.0.10's render
// at 160x120 without antialiasing: povray +Isweep.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 scale 1.5 } }
background { rgb <0.5, 0.6, 0.8> }
sphere_sweep { linear_spline 3, <-4, -0.5, 1>, 0.5 <-3, 1.5, 1>, 0.25 <-1.5, 1.5, 0>, 0.4
               pigment { rgb <1, 0.4, 0.2> } finish { phong 0.5 } }
sphere_sweep { b_spline 6, <-2, -0.5, -1>, 0.3 <-1, 1, -1.5>, 0.5 <0, -0.5, -1>, 0.3
               <1, 1.2, -1.2>, 0.4 <2, -0.5, -1.5>, 0.2 <3, 1, -1>, 0.4
               tolerance 1e-4 pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.5 } }
sphere_sweep { cubic_spline 5, <0, 0, 3>, 0.3 <1, 0, 2>, 0.35 <2, 2, 2.5>, 0.5 <3.5, 0.5, 1>, 0.25
               <4, 0, 0>, 0.3 pigment { rgb <0.3, 0.4, 1> } finish { phong 0.5 } }
sphere_sweep { linear_spline 3, <0.2, -0.6, -3.2>, 0.4 <1.4, -0.6, -3.2>, 0.4 <1.9, 0.6, -3.5>, 0.3
               pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.6 }
               interior { ior 1.4 } }
