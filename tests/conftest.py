"""Shared by every test directory: pytest.approx(expected, rel=r) compares with the relative
tolerance r alone.

pytest adds an absolute tolerance of 1e-12 to any rel= that comes without abs=. In SI units the
quantities these tests compare are often far below that (a bed's spin energy 1e-13 J, a contact
force 1e-6 N, a displacement 1e-9 m), so that rel=1e-9 there let values 0.2 % apart pass: a test
that could not fail. Here rel= without abs= means abs=0; a comparison that needs an absolute
tolerance (an expected zero) says so with abs=.
"""
import pytest

_pytest_approx = pytest.approx


def _approx_relative(expected, rel=None, abs=None, nan_ok=False):
    if rel is not None and abs is None:
        abs = 0.0
    return _pytest_approx(expected, rel=rel, abs=abs, nan_ok=nan_ok)


pytest.approx = _approx_relative
