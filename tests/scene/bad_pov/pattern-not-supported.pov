// error: 3:24: pigment pattern "bozo" is not supported yet
// note: docs/povray.md lists what glint reads
plane { y, 0 pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } }
