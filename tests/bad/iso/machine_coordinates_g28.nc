; expect: 2:1: a move to the reference point (G28) has no APT form: GOTO points are the part's, and GOHOME is the FROM point in APT but the machine's home (every axis) to many posts, so no statement says it; translate to an NC dialect instead
G91 G28 Z0.
G90
