// error: 4:1: ground fog (fog_type 2) needs fog_alt > 0, got 0
#version 3.7;
camera { location <0, 1, -5> look_at 0 }
fog { fog_type 2 distance 4 color rgb 1 }
