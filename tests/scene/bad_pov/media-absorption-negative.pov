// error: 2:64: media absorption must not be negative
sphere { 0, 1 pigment { rgbt 1 } interior { media { absorption -0.5 } } }
