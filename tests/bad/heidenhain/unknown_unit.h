; expect: 2:15: unknown unit 'CM'
0 BEGIN PGM T CM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 END PGM T MM
