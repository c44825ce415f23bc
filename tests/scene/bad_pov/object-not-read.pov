// error: 3:1: POV-Ray's sphere_sweep is not supported yet
// note: docs/povray.md lists what glint reads
sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }
