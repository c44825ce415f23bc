// error: 3:24: "bozo" is not supported as a pigment yet
// note: docs/povray.md lists what glint reads
plane { y, 0 pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } }
