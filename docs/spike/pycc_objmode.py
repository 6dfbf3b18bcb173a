from numba.pycc import CC
from instrument.predicates import orient2d, incircle
cc = CC("pred_aot"); cc.output_dir = "."
@cc.export("o2d", "f8(f8,f8,f8,f8,f8,f8)")
def o2d(a,b,c,d,e,f):
    return orient2d(a,b,c,d,e,f)
cc.compile()
