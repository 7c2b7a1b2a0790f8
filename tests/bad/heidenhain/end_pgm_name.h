; expect: 5:11: END PGM name B differs from BEGIN PGM's A: the control pairs them by name; give both the same
0 BEGIN PGM A MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 END PGM B MM
