# The input segments' endpoints (endpoints.py).
ctypedef Py_ssize_t Index

cpdef enum:             # check_endpoints's verdict on each segment
    KEPT = 0
    BAD_FIRST = 1       # the first endpoint is not a vertex
    BAD_SECOND = 2      # the second endpoint is not a vertex
    COINCIDENT = 3      # both endpoints are at the same place

cpdef Index check_endpoints(long long[:, ::1] seg, long long[::1] dup, double[:, ::1] xy, long long[:, ::1] rows, signed char[::1] verdict)
cpdef bint pair_keys(long long[:, ::1] rows, long long[::1] keys)
cpdef bint all_different(long long[::1] sorted_keys)
