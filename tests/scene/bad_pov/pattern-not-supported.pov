// error: 3:24: pigment pattern "julia" is not supported yet
// note: docs/povray.md lists what glint reads
plane { y, 0 pigment { julia <0.3, 0.4> 50 color_map { [0 rgb 0] [1 rgb 1] } } }
