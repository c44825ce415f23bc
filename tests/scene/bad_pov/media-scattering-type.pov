// error: 2:66: the number as the scattering type must be a whole number from 1 to 5, got 6
sphere { 0, 1 pigment { rgbt 1 } interior { media { scattering { 6, 0.1 } } } }
