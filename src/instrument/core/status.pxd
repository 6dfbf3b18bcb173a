# Kernel outcomes (status.py).
cpdef enum:
    DONE = 0          # finished
    NEED_ROOM = 1     # grow the mesh (or a table) and call again
    NEED_BUFFER = 2   # grow the scratch buffer and call again
    FAILED = 3        # gave up: the input cannot be handled this way
    PRECISION = 4     # a point the algorithm must make is not representable
    PAUSE = 5         # a slice of work is done; call again (lets Python see Ctrl-C)
