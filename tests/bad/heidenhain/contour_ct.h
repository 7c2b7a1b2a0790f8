; expect: 5:3: 'CT' is not supported
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 CT X+10 Y+5
9 END PGM T MM
