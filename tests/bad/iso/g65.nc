; expect: 2:1: call of O9010: no label O9010 in this file, and no directory to look for its file O9010, O9010.nc or 9010.nc in (--include-dir DIR names the directory that holds it)
G65 P9010 A1. B2.
M30
