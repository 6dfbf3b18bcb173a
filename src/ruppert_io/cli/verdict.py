"""``-C``: the exact checker's verdict on the final mesh, in Triangle's words.

The checker (``instrument.check``) is loaded only when ``-C`` is given.
"""

from __future__ import annotations

from typing import TextIO


#: What -C prints (Triangle's sentences; its exact -C output is not in our reference).
CHECK_TEXT = {
    "consistency": "Checking consistency of mesh...",
    "consistent": "  In my considered opinion, the mesh is fine.",
    "delaunay": "Checking Delaunay property of mesh...",
    "is_delaunay": "  By virtue of my perceptive intelligence, I declare the mesh Delaunay.",
    "problem": "  !! !! {}",
    "count": "  !! !! !! !! Precisely {} problem{} found.",
}


def print_verdict(mesh, out: TextIO, quiet: bool) -> None:
    """-C: the mesh checker's verdict, in Triangle's words."""
    from instrument.check import check_mesh

    def report(header: str, fine: str, problems: list[str]) -> None:
        if not quiet:
            print(CHECK_TEXT[header], file=out)
        if problems:
            for p in problems:
                print(CHECK_TEXT["problem"].format(p), file=out)
            n = len(problems)
            print(CHECK_TEXT["count"].format(n, "" if n == 1 else "s"), file=out)
        elif not quiet:
            print(CHECK_TEXT[fine], file=out)

    consistency = check_mesh(mesh, delaunay=False)
    everything = check_mesh(mesh)
    report("consistency", "consistent", consistency)
    report("delaunay", "is_delaunay", [p for p in everything if p not in consistency])
