// error: 2:12: cannot find the font "no-such-font.ttf"
text { ttf "no-such-font.ttf" "glint" 0.2, 0 }
