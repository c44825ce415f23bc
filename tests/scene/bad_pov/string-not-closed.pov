// error: 2:17: string is not closed: " without its "
#declare Name = "glint
