// error: 3:44: pretrace_end must be in [0, 1], got 1.5
#version 3.7;
global_settings { radiosity { pretrace_end 1.5 count 100 } }
sphere { 0, 1 pigment { rgb 1 } }
