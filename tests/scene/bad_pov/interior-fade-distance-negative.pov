// error: 2:59: fade distance must be finite and >= 0
sphere { 0, 1 pigment { rgbf 1 } interior { fade_distance -1 } }
