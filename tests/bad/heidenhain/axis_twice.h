; expect: 4:9: axis 'X' given twice
0 BEGIN PGM T MM
1 M128
2 L X+0 X+1 Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
