// error: 2:74: pigment pattern "density_file" is not supported yet
sphere { 0, 1 pigment { rgbt 1 } interior { media { emission 1 density { density_file df3 "cloud.df3" } } } }
