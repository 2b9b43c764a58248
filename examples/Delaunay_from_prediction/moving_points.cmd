# N = 50000 particles, 5 frames: a few seconds under ctest (the demo default is 200000 10)
50000 5
