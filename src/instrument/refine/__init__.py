"""Quality refinement, the pipeline's fourth stage (being ported: see refine_numba.py)."""
