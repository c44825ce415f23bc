// error: 2:64: medium absorption must be finite and >= 0
sphere { 0, 1 pigment { rgbt 1 } interior { media { absorption -0.5 } } }
