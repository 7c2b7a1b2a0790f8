; expect: 3:1: a retract along the tool axis to the end of travel (M140 MB MAX) has no APT form: GOTO points are the part's, and GOHOME is the FROM point in APT but the machine's home (every axis) to many posts, so no statement says it; translate to an NC dialect instead
0 BEGIN PGM T MM
1 M140 MB MAX
2 END PGM T MM
