import os, time
from setuptools import setup, Extension
from Cython.Build import cythonize
t = time.time()
ext = [Extension("dc", ["dc.py"], extra_compile_args=["-O3", "-ffp-contract=off"])]
setup(ext_modules=cythonize(ext, annotate=True, quiet=True))
print("build seconds", time.time() - t)
