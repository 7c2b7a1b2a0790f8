; expect: 2:1: call of O1000: no label O1000 in this file, and no directory to look for its file O1000, O1000.nc or 1000.nc in (--include-dir DIR names the directory that holds it)
N20 M98 P1000
M30
