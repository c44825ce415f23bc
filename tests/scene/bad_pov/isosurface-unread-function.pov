// error: 4:14: the isosurface's function uses f_ridged_mf, which glint does not compute yet
// note: docs/povray.md lists what glint reads
#declare f_ridged_mf = function { internal(59) }
isosurface { function { y - f_ridged_mf(x, y, z, 0.5, 2, 6, 1, 2, 1) } contained_by { box { -1, 1 } } }
