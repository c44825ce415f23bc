// error: 4:25: "Ring" takes 2 arguments, got 3
// A declared function called with the wrong number of arguments.
#declare Ring = function(r, h) { sqrt(r * r + h * h) - 1 }
isosurface { function { Ring(x, y, z) } }
