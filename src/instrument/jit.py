"""The decorators every engine kernel uses, and stack scratch space.

``kernel`` compiles a hot, non-allocating function without numba's reference
counting (``_nrt=False``).  The mesh is a NamedTuple of seven arrays; with
reference counting on, every call that LLVM does not inline increments and
decrements each array's count atomically, which made one edge flip cost about
1.4 us instead of 60 ns (measured).  Functions called from a ``kernel`` are
compiled under the same flag, so they must not create heap arrays either:
``scratch(n)`` gives a float64 work array on the stack instead (the exact
predicates' expansions).  No kernel may reassociate floating-point
arithmetic (numba's fast-math option): that would break the error-free
transformations of the exact predicates.

``kernel_inline`` is for the small helpers a hot loop calls once per
triangle or per flip.  A call that LLVM does not inline passes every array
argument as its seven fields (data pointer, shape, strides, ...): a helper
taking the refiner (18 arrays) and the mesh pushes about 200 words on the
stack, which was the hottest code of a refinement run.  numba inlines these
itself, whatever their size; each call site is compiled again, so keep the
list short.
"""

import numpy as np
from numba import config, njit, types
from numba.core import cgutils
from numba.extending import intrinsic
from numba.np.arrayobj import make_array, populate_array

kernel = njit(cache=True, _nrt=False)
kernel_inline = njit(cache=True, _nrt=False, inline="always")
allocating = njit(cache=True)


def _stack_intrinsic(dtype):
    """An intrinsic ``f(n)`` returning a 1-D ``dtype`` array of ``n`` (a literal)
    elements in the calling function's stack frame."""
    arrty = types.Array(dtype, 1, "C")

    @intrinsic
    def stack_array(typingctx, size):
        if not isinstance(size, types.IntegerLiteral):
            return None
        n = size.literal_value

        def codegen(context, builder, sig, args):
            # alloca_once puts the buffer in the function's entry block, so a
            # call inside a loop does not grow the stack.
            count = context.get_constant(types.intp, n)
            ptr = cgutils.alloca_once(builder, context.get_data_type(dtype), size=count)
            ary = make_array(arrty)(context, builder)
            itemsize = context.get_constant(types.intp, context.get_abi_sizeof(context.get_data_type(dtype)))
            populate_array(ary, data=ptr, shape=[count], strides=[itemsize], itemsize=itemsize, meminfo=None)
            return ary._getvalue()

        return arrty(size), codegen

    return stack_array


if config.DISABLE_JIT:

    def scratch(n):
        """A float64 work array of ``n`` (a literal) elements, uninitialised.

        Lives in the caller's stack frame: never return it."""
        return np.empty(n)

    def iscratch(n):
        """Like ``scratch``, for int64."""
        return np.empty(n, dtype=np.int64)

else:
    scratch = _stack_intrinsic(types.float64)
    iscratch = _stack_intrinsic(types.int64)
