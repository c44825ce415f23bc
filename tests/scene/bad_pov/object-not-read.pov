// error: 3:1: POV-Ray's ovus is not supported yet
// note: docs/povray.md lists what glint reads
ovus { 1, 0.5 }
