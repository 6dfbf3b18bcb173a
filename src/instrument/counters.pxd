# The work counters' slots (counters.py names them), for the kernels.
cpdef enum:
    C_CREATED = 0
    C_DELETED = 1
    C_INCIRCLE = 2
    C_ORIENT = 3
    C_CIRCUMCENTER = 4
    C_FLIP = 5
    C_WALK = 6
    C_SEGMENT_SPLIT = 7
    C_STEINER = 8
    C_REJECTED = 9
    C_DELETED_VERTEX = 10
    C_QUEUE_POP = 11
    C_STALE_POP = 12
    C_DUPLICATE = 13
    C_UNDONE = 14
