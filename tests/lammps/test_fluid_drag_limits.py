"""fix fluid/drag: bin counts beyond the limit end in an ERROR naming bins (issue 46).

The product nx ny nz overflowed a 32-bit int: bins 65536 65537 1 crashed (segmentation fault),
bins 50000 50000 1 aborted with a C++ exception. The limit, 1e8 bins, keeps the two per-rank
arrays (16 bytes a bin) within memory and the bin index within an int.
"""
import pytest

from test_fluid_drag import sphere


@pytest.mark.parametrize("bins,count", [
    ("65536 65537 1", "4295032832"),    # wraps a 32-bit int to 65536
    ("50000 50000 1", "2500000000"),    # wraps to a negative int
    ("1000 1000 101", "101000000"),     # fits an int, beyond the limit
])
def test_bin_count_beyond_the_limit_is_an_error(lmp, bins, count):
    lmp(sphere(extra=f"hindrance richardson-zaki 4.65 bins {bins}", steps=1), check=False)
    error = next((line for line in lmp.log.splitlines() if "ERROR" in line), None)
    assert error is not None, lmp.log[-1500:]
    assert f"bins {bins} = {count} bins is out of range (allowed: nx ny nz <= 100000000" in error, error


def test_bins_below_one_is_an_error(lmp):
    lmp(sphere(extra="hindrance richardson-zaki 4.65 bins 4 0 4", steps=1), check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert "bins = 0 is out of range (allowed: >= 1)" in error, error
