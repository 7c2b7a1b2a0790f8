; expect: 2:1: a move in machine coordinates (G53, G28, G30, SUPA, M91, M92) is not translated: the source machine's axis positions mean nothing on another machine
G91 G28 Z0.
G90
