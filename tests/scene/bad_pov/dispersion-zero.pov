// error: 3:56: dispersion must be in (0.5, 2), got 0
// note: 1 is none; POV-Ray suggests 1.01 to 1.1
sphere { 0, 1 pigment { rgbf 1 } interior { dispersion 0 } }
