light_source { <0, 5, 0> color 1 spotlight point_at 0 radius 10 falloff 20 }
light_source { <0, 5, 0> color 1 area_light x, z, 2, 2 circular orient fade_distance 3 fade_power 2 }
light_source { <0, 5, 0> color rgbf <1, 1, 1, 0.5> parallel point_at -y }
global_settings { ambient_light 0.5 max_trace_level 3 }
background { color rgbt <0, 0, 0.2, 0> }
union { torus { 1, 0.2 } disc { 0, y, 1, 0.5 } cone { 0, 1, y, 0 open } rotate 45*x }
intersection { plane { y, 0 } sphere { 0, 1 } finish { specular 0.5 roughness 0.01 } }
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
mesh { triangle { 0, x, y } smooth_triangle { 0, z, x, z, y, z } }
