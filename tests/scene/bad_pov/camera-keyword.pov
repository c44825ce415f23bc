// error: 3:40: "omnimax" is not supported in a camera yet
// note: docs/povray.md lists what glint reads
camera { location <0, 0, -5> look_at 0 omnimax }
