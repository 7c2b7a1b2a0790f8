; expect: 4:5: word 'X' has no value
0 BEGIN PGM T MM
1 M128
2 L X Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
