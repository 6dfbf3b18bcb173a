# Ties and duplicates among sorted points (distinct.py).
ctypedef Py_ssize_t Index

cpdef bint has_x_ties(double[:, ::1] xy, long long[::1] order)
cpdef Index mark_duplicates(double[:, ::1] xy, long long[::1] order, long long[::1] dup)
