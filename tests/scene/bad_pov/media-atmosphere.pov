// error: 2:1: POV-Ray's media is not supported yet
media { scattering { 1, 0.01 } }
