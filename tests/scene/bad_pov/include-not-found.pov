// error: 3:10: cannot find the include file "nowhere.inc"
// note: tests/scene/bad_pov
#include "nowhere.inc"
