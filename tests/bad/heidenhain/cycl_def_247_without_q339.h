; expect: 3:3: CYCL DEF 247 (datum setting) without Q339 in its block: the preset it selects is not known
0 BEGIN PGM T MM
1 CYCL DEF 247 DATUM SETTING
  Q339=+1 ;DATUM NUMBER
2 END PGM T MM
