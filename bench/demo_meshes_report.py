#!/usr/bin/env python3
"""The report of bench/demo_meshes.sh: each mesh's reference beside libmoa's and CGAL's results.

Usage: demo_meshes_report.py RESULTS_DIR REVISION NAME... > report.md
RESULTS_DIR holds NAME.reference.json, NAME.moa.json, NAME.moa.stats.json, NAME.cgal.tried,
NAME.cgal.json and NAME.cgal.seconds as the script wrote them (`moa check --json`, `moa
reconstruct --stats`); a missing file is a run that failed or timed out (CGAL's runner was
tried where NAME.cgal.tried exists).
"""
import datetime
import json
import os
import sys


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def shape(check):
    """Closed or open, components and Euler characteristic: what 'the same surface' compares."""
    if check is None:
        return None
    return (check["closed"], check["components"], check["euler_characteristic"])


def describe(check):
    if check is None:
        return "failed", "", "", ""
    state = "closed" if check["closed"] else "%d open" % check["boundary_edges"]
    genus = str(check["genus"]) if check.get("genus_defined", True) else "-"
    return state, str(check["components"]), genus, "ok" if check["contract"]["ok"] else "FAIL"


def main():
    results, revision, names = sys.argv[1], sys.argv[2], sys.argv[3:]
    rows = []
    closed_refs = same_moa = same_cgal = contract_moa = contract_cgal = ran_cgal = 0
    # Closed references that hold the contract themselves: the surfaces a valid result can equal.
    valid_refs = valid_moa = valid_cgal = 0
    for name in names:
        at = lambda suffix: os.path.join(results, name + suffix)
        ref, moa, cgal = load(at(".reference.json")), load(at(".moa.json")), load(at(".cgal.json"))
        stats = load(at(".moa.stats.json"))
        cgal_ran = os.path.exists(at(".cgal.tried"))
        if ref is None:
            continue
        # A failed run's shape is None, never the reference's.
        moa_same, cgal_same = shape(moa) == shape(ref), shape(cgal) == shape(ref)
        closed_refs += ref["closed"]
        valid = ref["closed"] and ref["contract"]["ok"]
        valid_refs += valid
        valid_moa += valid and moa_same
        valid_cgal += valid and cgal_same
        same_moa += moa_same
        contract_moa += moa is not None and moa["contract"]["ok"]
        if cgal_ran:
            ran_cgal += 1
            same_cgal += cgal_same
            contract_cgal += cgal is not None and cgal["contract"]["ok"]
        seconds = None
        if os.path.exists(at(".cgal.seconds")):
            with open(at(".cgal.seconds")) as f:
                seconds = float(f.read())
        cells = [name, "{:,}".format(ref["vertices"])]
        cells += list(describe(ref))
        cells += list(describe(moa))
        cells.append("%.2f" % (stats["reconstruct_ms"] / 1000) if stats else "")
        cells += list(describe(cgal)) if cgal_ran else ["not run", "", "", ""]
        cells.append("%.2f" % seconds if seconds is not None else "")
        rows.append(cells)

    print("# Meshes no test uses: CGAL's demo data\n")
    print("`bench/demo_meshes.sh` at %s, %s. The vertices of every mesh of 300-50,000 vertices in"
          % (revision, datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")))
    print("CGAL's demo data (Debian's `libcgal-demo`) are reconstructed by libmoa (default")
    print("parameters) and by CGAL's advancing front (its defaults); `moa check` looks at every")
    print("result and at the mesh the vertices came from (the reference). Some references are open,")
    print("some are not manifold or cross themselves (their contract column says FAIL).")
    shared = os.environ.get("SHARED_LEFT_OUT", "").split()
    if shared:
        print("The meshes also in the shared data, which the tests and the benchmark use, are left"
              " out: %s.\n" % ", ".join(shared))
    else:
        print()
    print("- %d meshes, %d of them closed." % (len(rows), closed_refs))
    print("- The same surface as the reference (closed or not, components, Euler characteristic):"
          " libmoa %d of %d, CGAL's advancing front %d of %d." % (same_moa, len(rows), same_cgal,
                                                                 ran_cgal))
    print("- Of the %d closed references that hold the contract themselves (the other closed ones"
          " break it: they cross themselves, or their faces are not oriented consistently): the"
          " same surface from libmoa on %d, from CGAL's advancing front on %d."
          % (valid_refs, valid_moa, valid_cgal))
    print("- Contract C1-C5 held: libmoa %d of %d, CGAL's advancing front %d of %d.\n"
          % (contract_moa, len(rows), contract_cgal, ran_cgal))
    head = ["mesh", "vertices", "reference", "comp.", "genus", "C1-C5", "libmoa", "comp.",
            "genus", "C1-C5", "s", "CGAL", "comp.", "genus", "C1-C5", "s"]
    print("| " + " | ".join(head) + " |")
    print("|" + "|".join("---" if i in (0, 2, 6, 11) else "--:" for i in range(len(head))) + "|")
    for cells in rows:
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
