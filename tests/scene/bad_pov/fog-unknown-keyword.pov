// error: 5:30: "fog_depth" is not supported in a fog yet
// note: docs/povray.md lists what glint reads
#version 3.7;
camera { location <0, 1, -5> look_at 0 }
fog { distance 4 color rgb 1 fog_depth 3 }
