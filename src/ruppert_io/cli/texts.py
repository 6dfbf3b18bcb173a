"""What the command says about itself: its usage line, ``-h``'s text and ``--version``.

``docs/cli.md`` quotes ``LONG_HELP`` word for word (a test keeps the two
equal), so a change here goes there too.
"""

from __future__ import annotations


USAGE = "ruppert [-prq__a__uAcDjevngBPNEIOXzo_YS__iFlsCQVh] input_file"

SHORT_HELP = f"""{USAGE}
    -p  Triangulates a Planar Straight Line Graph (.poly file).
    -r  Refines a previously generated mesh.
    -q  Quality mesh generation.  A minimum angle may be specified.
    -a  Applies a maximum triangle area constraint.
    -u  Applies a user-defined triangle constraint.
    -A  Applies attributes to identify triangles in certain regions.
    -c  Encloses the convex hull with segments.
    -D  Conforming Delaunay:  all triangles are truly Delaunay.
    -j  Jettison unused vertices from output .node file.
    -e  Generates an edge list.
    -v  Generates a Voronoi diagram.
    -n  Generates a list of triangle neighbors.
    -g  Generates an .off file for Geomview.
    -B  Suppresses output of boundary information.
    -P  Suppresses output of .poly file.
    -N  Suppresses output of .node file.
    -E  Suppresses output of .ele file.
    -I  Suppresses mesh iteration numbers.
    -O  Ignores holes in .poly file.
    -X  Suppresses use of exact arithmetic.
    -z  Numbers all items starting from zero (rather than one).
    -o2 Generates second-order subparametric elements.
    -Y  Suppresses boundary segment splitting.
    -S  Specifies maximum number of added Steiner points.
    -i  Uses incremental method, rather than divide-and-conquer.
    -F  Uses Fortune's sweepline algorithm, rather than d-and-c.
    -l  Uses vertical cuts only, rather than alternating cuts.
    -s  Force segments into mesh by splitting (instead of using CDT).
    -C  Check consistency of final mesh.
    -Q  Quiet:  No terminal output except errors.
    -V  Verbose:  Detailed information on what I'm doing.
    -h  Help:  Detailed instructions for ruppert.
Long options: --strategy NAME  --steiner offcenter|circumcenter  --seed N
    --work-json PATH  --trace PATH  --format FMT[,FMT...]  --progress
    --max-vertices N  --threads N  --version
"""

LONG_HELP = f"""ruppert: a two-dimensional quality mesh generator and Delaunay triangulator
that behaves like J. R. Shewchuk's Triangle 1.6 and counts its own work.

Usage:
    {USAGE} [long options]

The input is a set of points (file.node), a planar straight line graph
(file.poly), or an earlier mesh to refine (file.node + file.ele, with -r).
Naming file.poly turns on -p, file.ele turns on -r, and file.area turns on -r
with per-triangle area bounds read from file.area.  Output goes to the input's
name with the next iteration number: A.poly gives A.1.node, A.1.ele, A.1.poly;
refining A.1 gives A.2.*.  Files are numbered from 0 or 1, as the input is.
The input may also be a mesh file meshio reads (mesh.vtu, mesh.msh,
mesh.mesh, ...): its points, its line cells as segments with -p, its
triangles with -r; mesh.vtu gives mesh.1.node, mesh.1.ele.

Switches are single letters; they may be grouped (-pq30a0.1) or separate
(-p -q30 -a0.1), and may come before or after the file name.  Numbers follow
q, a, S and o directly.  Unlike Triangle, the numbers after q and a may carry an
exponent: -a1e-4 is a maximum area of 0.0001.

  What to triangulate
    -p      Read a planar straight line graph (.poly): vertices, segments,
            holes and regional attributes/area bounds; build a constrained
            Delaunay triangulation (conforming with -q, -a, -u, -D or -s).
    -r      Refine the mesh in file.node and file.ele (and file.poly with -p,
            file.area with a bare -a).  Cannot be combined with -I.
    -c      Also enclose the convex hull with segments.
    -O      Ignore the holes listed in the .poly file.

  Quality
    -q[deg] Add Steiner points until no angle is below deg (default 20).
            Termination is guaranteed up to about 28.6 degrees.
    -a[A]   Bound triangle areas by A; a bare -a uses the area bounds of the
            .poly regions (or of the .area file with -r).  Both may be given.
    -u      Refine triangles that fail the user test (Triangle's stock test).
    -D      Conforming Delaunay: every triangle is truly Delaunay.
    -Y      Do not split boundary segments; -YY: do not split any segment.
    -S[n]   Add at most n Steiner points (no number: none).
    -s      Recover segments by splitting them rather than by flipping.
    -X      Do not use exact arithmetic (for comparison only).
    -i -l   Incremental Delaunay; vertical cuts only (-F: divide and conquer).

  Output
    -A      Give each triangle the attribute of the region it lies in.
    -j      Leave unused vertices (duplicates, eaten vertices) out of .node.
    -e      Write the edges (.edge).
    -v      Write the Voronoi diagram (.v.node, .v.edge).
    -n      Write the triangles' neighbours (.neigh).
    -g      Write a Geomview file (.off).
    -o2     Write six-node (second-order) triangles.
    -B      Write no boundary markers.
    -P -N -E  Do not write the .poly / .node / .ele file.
    -I      Write to the input's name without iteration number (the .node and
            .poly files that were read are not overwritten).
    -z      Number items from 0 when the input does not say.

  Console
    -Q      Quiet: print only warnings' absence and errors.
    -V      Verbose: also print the quality statistics (areas, edges, aspect
            ratios, angle histograms), Triangle's algorithmic statistics, and
            every work counter of the engine ("Work statistics").
    -C      Check the final mesh: consistency and the Delaunay property.
    -h      Print this text.

Long options (ruppert's own):
    --strategy NAME     Order in which bad triangles are split (default
                        "triangle", Triangle 1.6's order).
    --steiner offcenter|circumcenter
                        Where a bad triangle is split (default offcenter).
    --seed N            Seed of randomised strategies (default 0).
    --work-json PATH    Write the work counters as JSON.
    --trace PATH        Write one CSV row per vertex insertion.
    --format FMT        Also write the mesh in meshio's format FMT, e.g.
                        vtu, gmsh, gmsh22, xdmf, medit, exodus, stl, obj
                        (comma-separated for several; every format meshio
                        writes, docs/cli.md lists what each keeps).  "msh"
                        means Gmsh 2.2 here (meshio would take it as ANSYS).
                        xdmf, med, h5m and hmf need h5py, exodus netCDF4
                        (pip install "ruppert[formats]").
    --progress          Show the progress display from the start (on a
                        terminal it appears anyway once a run has taken
                        about a second; never with -Q or when stderr is not
                        a terminal).
    --max-vertices N    Stop refinement with an error once the mesh has more
                        than N vertices.  The default is derived from the
                        input: max(1,000,000 (4,000,000 without -q), 1,000
                        per input vertex and segment), plus 4 per maximum
                        area of domain with -a, raised to the input plus
                        -S's budget, and at most what half of this
                        machine's memory holds.  An area bound whose mesh
                        needs more fails at once.
    --threads N         Threads for the Delaunay triangulation of a large
                        input (default: every core this process may use).
                        The mesh and the work counts are the same on any
                        number.
    --version           Print ruppert's version.

A minimum angle above 34 degrees prints a warning: Triangle's documentation
says refinement is guaranteed to terminate up to 28.6 degrees and usually
does up to 34; above that it may refine until the vertex limit.

Exit status: 0 on success, 1 on an error (one line starting with "Error:"),
130 when interrupted.
"""


def version() -> str:
    """The installed distribution's version (the engine's ``__version__``),
    read without importing the engine."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as dist_version

    try:
        return dist_version("ruppert")
    except PackageNotFoundError:
        return "0+unknown"
