; expect: 4:3: CYCL DEF 200 is not supported: fixed cycles are refused until kin5 reads them (their holes and pockets would be lost)
0 BEGIN PGM T MM
1 TOOL CALL 5 Z S3000
2 CYCL DEF 200 DRILLING ~
  Q200=2 ;SET-UP CLEARANCE ~
  Q201=-12 ;DEPTH
3 L X+10 Y+10 R0 FMAX
4 END PGM T MM
