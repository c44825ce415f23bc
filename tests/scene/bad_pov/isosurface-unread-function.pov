// error: 4:14: the isosurface's function uses f_noise3d, which glint does not compute yet
// note: docs/povray.md lists what glint reads
#declare f_noise3d = function { internal(76) }
isosurface { function { y - f_noise3d(x, y, z) } contained_by { box { -1, 1 } } }
