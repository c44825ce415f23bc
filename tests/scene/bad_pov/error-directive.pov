// error: 3:3: #error: this scene needs POV-Ray 4
#if (version < 4)
  #error "this scene needs POV-Ray 4"
#end
