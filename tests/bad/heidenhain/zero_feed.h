; expect: 4:25: feed move with F0: a zero feed rate never reaches the end point
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F0
9 END PGM T MM
