; expect: 3:1: G4: a dwell of iso is not translated into apt yet (it would become a comment)
G43.4 H1
G4 P1500
G1 X0. Y0. Z0. A10. C0. F100.
