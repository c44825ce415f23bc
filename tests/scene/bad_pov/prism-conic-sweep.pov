// error: 3:9: "conic_sweep" is not supported in a prism yet
// note: docs/povray.md lists what glint reads
prism { conic_sweep linear_spline 0.5, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
