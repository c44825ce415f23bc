// error: 4:3: "normal" is not supported as an object modifier yet
// note: docs/povray.md lists what glint reads
sphere { 0, 1
  normal { bumps 0.4 scale 0.2 }
}
