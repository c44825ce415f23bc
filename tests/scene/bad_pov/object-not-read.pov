// error: 3:1: POV-Ray's blob is not supported yet
// note: docs/povray.md lists what glint reads
blob { threshold 0.6 sphere { 0, 1, 1 } }
