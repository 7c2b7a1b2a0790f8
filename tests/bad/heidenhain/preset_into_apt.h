; expect: 3:1: preset 4: a work offset of heidenhain with no certain equivalent in apt (it selects none); --work-offset-map 4=... names the target's, or drops it with nothing after =
0 BEGIN PGM T MM
1 CYCL DEF 247 DATUM SETTING ~
  Q339=+4 ;DATUM NUMBER
2 END PGM T MM
