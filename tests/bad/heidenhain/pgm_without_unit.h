; expect: 2:3: BEGIN PGM needs a name and a unit
0 BEGIN PGM T
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 END PGM T MM
