// error: 2:86: medium eccentricity must be in (-1, 1)
sphere { 0, 1 pigment { rgbt 1 } interior { media { scattering { 5, 0.1 eccentricity 1.5 } } } }
