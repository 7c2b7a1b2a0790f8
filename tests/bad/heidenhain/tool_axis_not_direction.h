; expect: 4:3: tool-axis vector shorter than 0.001 is not a direction
0 BEGIN PGM T MM
1 M128
2 LN X+0 Y+0 Z+0 TX+0 TY+0 TZ+0.0000001 F100
9 END PGM T MM
