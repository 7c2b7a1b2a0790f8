; expect: 2:5: M98: a subprogram call is not supported (the motion it makes would be lost)
N20 M98 P1000
M30
