// error: 3:1: POV-Ray's quartic needs bounded_by or clipped_by in glint: its surface is unbounded, and glint searches it within their box
// note: docs/povray.md lists what glint reads
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> pigment { rgb 1 } }
