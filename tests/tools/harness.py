"""harness.py - the small test harness of the Python tool tests (test_ensemble.py, test_netcdf_outputs.py,
test_dem_to_scene.py): a decorator that lists a test, the failure a check raises with its reason, and the main
that runs the listed tests."""

TESTS = []


def test(fn):
    """Lists fn as a test, in order."""
    TESTS.append(fn)
    return fn


class Failure(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failure(what)


def main(doc, prefix, use_args):
    """Parses --cdmpm PATH [--work DIR] [--keep] [-k NAME], hands the arguments to use_args, runs the listed tests
    (those whose name contains NAME), prints PASS or FAIL per test and "N passed, M failed", and exits 1 if any
    failed. The work folder is a new temporary one unless --work; it is removed at the end unless --keep."""
    import argparse
    import os
    import shutil
    import sys
    import tempfile
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cdmpm", required=True, help="the cdmpm program")
    ap.add_argument("--work", help="work folder (default: a temporary one, removed unless --keep)")
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("-k", help="run only the tests whose name contains this")
    args = ap.parse_args()
    temporary = args.work is None
    args.work = args.work or tempfile.mkdtemp(prefix=prefix)
    os.makedirs(args.work, exist_ok=True)
    use_args(args)
    passed = failed = 0
    for fn in TESTS:
        if args.k and args.k not in fn.__name__:
            continue
        try:
            fn()
            print(f"PASS {fn.__name__}", flush=True)
            passed += 1
        except Failure as e:
            print(f"FAIL {fn.__name__}: {e}", flush=True)
            failed += 1
    print(f"{passed} passed, {failed} failed")
    if temporary and not args.keep:
        shutil.rmtree(args.work, ignore_errors=True)
    sys.exit(1 if failed else 0)
