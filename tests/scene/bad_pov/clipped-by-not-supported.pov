// error: 4:3: "clipped_by" is not supported as an object modifier yet
// note: docs/povray.md lists what glint reads
sphere { 0, 1
  clipped_by { plane { y, 0 } }
}
