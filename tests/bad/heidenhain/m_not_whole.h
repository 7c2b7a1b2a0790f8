; expect: 4:30: word 'M' needs a whole number
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100 M3.5
9 END PGM T MM
