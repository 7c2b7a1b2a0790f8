; expect: 4:1: block number out of range
0 BEGIN PGM T MM
1 M128
4444444444444444 L X+0 Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
