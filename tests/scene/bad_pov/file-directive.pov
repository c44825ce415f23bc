// error: 3:1: #fopen is not supported
// note: glint reads POV-Ray's directives
#fopen Log "log.txt" write
