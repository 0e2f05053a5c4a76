"""harness.py - the small test harness of the Python tool tests (test_ensemble.py, test_netcdf_outputs.py): a
decorator that lists a test, and the failure a check raises with its reason."""

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
