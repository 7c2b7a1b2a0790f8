; expect: 3:8: 'MB' in an M block is not supported (M140 MB retracts, M120 looks ahead: the machine would do something else)
0 BEGIN PGM T MM
1 M140 MB MAX
2 END PGM T MM
