; expect: 4:5: value out of range
0 BEGIN PGM T MM
1 M128
2 L X+10000000000 Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
