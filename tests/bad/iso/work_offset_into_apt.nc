; expect: 3:5: G59: a work offset of iso with no certain equivalent in apt (it selects none); --work-offset-map G59=... names the target's, or drops it with nothing after =
G43.4 H1
G90 G59
G1 X0. Y0. Z0. A10. C0. F100.
