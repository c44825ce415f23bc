// error: 3:12: text-not-a-font.pov is not a font FreeType reads (TrueType, OpenType)
// A scene file is no font.
text { ttf "text-not-a-font.pov" "glint" 0.2, 0 }
