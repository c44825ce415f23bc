// error: 3:1: #statistics is not supported
// note: glint reads POV-Ray's directives
#statistics "log"
