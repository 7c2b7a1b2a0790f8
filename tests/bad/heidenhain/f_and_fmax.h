; expect: 4:3: F and FMAX in one block
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100 FMAX
9 END PGM T MM
