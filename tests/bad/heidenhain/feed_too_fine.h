; expect: 4:25: the feed 0.0004 cannot be written with 3 decimals, the most the controller reads (it would read as 0)
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F0.0004
9 END PGM T MM
