// error: 3:43: comparisons and logic (>) in a function are not supported yet
// note: docs/povray.md lists what glint reads
isosurface { function { x * x + y * y + z > 1 } }
