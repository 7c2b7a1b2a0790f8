; expect: 4:5: parameter Q1 is read before it is assigned: its value is the machine's
0 BEGIN PGM T MM
1 M128
2 L X+Q1 Y+0 Z+0 B+0 C+0 F100
9 END PGM T MM
