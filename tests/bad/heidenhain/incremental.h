; expect: 4:5: incremental X (IX) from a position the program does not say: no absolute X since the start of the program, so the move would start from wherever the machine stands; program an absolute X before it
0 BEGIN PGM T MM
1 M128
2 L IX+1 Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
