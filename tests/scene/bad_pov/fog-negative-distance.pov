// error: 4:1: fog distance must be > 0, got -4
#version 3.7;
camera { location <0, 1, -5> look_at 0 }
fog { distance -4 color rgb 1 }
