"""The compiled banded LU (solve.banded.band_solve) against LAPACK's through scipy: the same solution
(to round-off: bitwise on Debian's stack, within an ulp or two where PyPI's OpenBLAS orders its sums
otherwise), pivoting where the diagonal is small, singular matrices told, and the shift added to the
diagonal; the compiled Cholesky's verdict and the inverse iteration's smallest eigenvalue against
LAPACK's factorisation and eigensolver."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import scipy.linalg

from yadearch.children import child_environment
from yadearch.solve import banded


def random_band(n: int, rng: np.random.Generator) -> np.ndarray:
    dense = np.zeros((n, n))
    for i in range(n):
        for j in range(max(0, i - banded.BAND), min(n, i + banded.BAND + 1)):
            dense[i, j] = rng.normal()
    return dense


@pytest.mark.parametrize("n", [3, 4, 11, 16, 159])
def test_the_solution_is_lapacks(n):
    rng = np.random.default_rng(n)
    for _ in range(10):
        dense, b, shift = random_band(n, rng), rng.normal(size=n), float(rng.normal())
        ab = banded.from_dense(dense)
        x = banded.solve(ab, b, shift)
        shifted = ab.copy()
        shifted[banded.BAND] += shift
        reference = scipy.linalg.solve_banded((banded.BAND, banded.BAND), shifted, b)
        np.testing.assert_allclose(x, reference, rtol=1e-12, atol=1e-12 * np.abs(reference).max())
        np.testing.assert_allclose((dense + shift * np.eye(n)) @ x, b, atol=1e-9 * np.abs(b).max() * n)


def test_a_zero_diagonal_is_pivoted_around():
    dense = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 2.0], [0.0, 3.0, 1.0]])
    x = banded.solve(banded.from_dense(dense), np.array([1.0, 2.0, 3.0]))
    np.testing.assert_allclose(dense @ x, [1.0, 2.0, 3.0])


def test_a_singular_tangent_is_told():
    dense = np.array([[1.0, 2.0, 0.0], [2.0, 4.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(np.linalg.LinAlgError):
        banded.solve(banded.from_dense(dense), np.ones(3))
    _, singular = banded.band_solve(banded.from_dense(dense), np.ones(3), 0.0)
    assert singular


def symmetric_part(dense: np.ndarray) -> np.ndarray:
    """The symmetric part of a matrix, whose definiteness decides stability."""
    return 0.5 * (dense + dense.T)


@pytest.mark.parametrize("n", [3, 16, 159])
def test_the_stability_verdict_is_lapacks_cholesky(n):
    """The compiled Cholesky says positive definite exactly where LAPACK's factorisation exists."""
    rng = np.random.default_rng(100 + n)
    verdicts = []
    for _ in range(40):
        dense = random_band(n, rng) + rng.normal(3.0, 2.0) * np.eye(n)  # about half positive definite
        try:
            scipy.linalg.cholesky(symmetric_part(dense))
            expected = True
        except np.linalg.LinAlgError:
            expected = False
        assert banded.positive_definite(banded.from_dense(dense)) == expected
        verdicts.append(expected)
    assert any(verdicts) and not all(verdicts)


def _settles(ab: np.ndarray) -> bool:
    """Whether inverse iteration on a stable matrix settles (the eigensolver is not asked)."""
    factor, stable = banded.cholesky_upper(ab)
    floor = banded.ROUNDOFF_RESIDUAL * float(np.abs(ab).sum(axis=0).max())
    settled = banded._inverse_iteration(ab, factor, banded.INVERSE_ITERATIONS, banded.INVERSE_RESIDUAL, floor)[1]
    return stable and settled


def soft_mode(dense: np.ndarray, ratio: float) -> np.ndarray:
    """The symmetric part of `dense` shifted so that its smallest eigenvalue is `ratio` of the gap to the
    next: a stable state with one soft mode, as an arch's tangent has one near a fold."""
    symmetric = symmetric_part(dense)
    values = np.linalg.eigvalsh(symmetric)
    return symmetric + (ratio * (values[1] - values[0]) - values[0]) * np.eye(len(dense))


@pytest.mark.parametrize("n", [3, 16, 159])
def test_the_smallest_eigenvalue_is_the_eigensolvers(n):
    """Stable states with a soft mode by inverse iteration, which settles; others (stable ones with a
    crowded bottom, unstable ones) by the eigensolver: the same value to round-off of the matrix's norm."""
    rng = np.random.default_rng(200 + n)
    for make in (lambda d: soft_mode(d, 0.2), lambda d: d + 12.0 * np.eye(n), lambda d: d):
        for _ in range(10):
            dense = make(random_band(n, rng))
            expected = np.linalg.eigvalsh(symmetric_part(dense))[0]
            found = banded.smallest_eigenvalue(banded.from_dense(dense))
            assert found == pytest.approx(expected, rel=1e-9, abs=1e-12 * np.abs(dense).max() * n)
    assert all(_settles(banded.from_dense(soft_mode(random_band(n, rng), 0.2))) for _ in range(10))


def test_a_nearly_singular_stable_state_settles():
    """A stable state next to a fold (smallest eigenvalue 1e-9 of the largest) settles by inverse
    iteration at the round-off of its product with a vector, with the eigensolver's value."""
    n = 60
    dense = symmetric_part(random_band(n, np.random.default_rng(5)))
    values = np.linalg.eigvalsh(dense)
    dense += (1e-9 * np.abs(values).max() - values[0]) * np.eye(n)
    ab = banded.from_dense(dense)
    assert _settles(ab)
    expected = np.linalg.eigvalsh(dense)[0]
    assert banded.smallest_eigenvalue(ab) == pytest.approx(expected, abs=1e-12 * np.abs(values).max())


SOFTEST_MODE_BITS = """
import hashlib
import numpy as np
from yadearch.solve import banded
rng = np.random.default_rng(3)
dense = rng.normal(size=(165, 165))
value, mode = banded.softest_mode(banded.from_dense(dense + dense.T))
print(value.hex(), hashlib.sha256(mode.tobytes()).hexdigest())
"""


def test_the_softest_mode_has_the_same_bits_whatever_the_blas_threads():
    # LAPACK's banded eigensolver on two threads gives other last bits than on one, and a stiff arch's
    # path follows a saddle's kick along that mode: a run from the command line (threads) ended 0.4 %
    # away from the same run in a campaign's worker (one thread) before the eigensolver ran on one
    answers = set()
    for threads in ("1", "2"):
        environment = child_environment(1) | {"OPENBLAS_NUM_THREADS": threads, "OMP_NUM_THREADS": threads}
        done = subprocess.run(
            [sys.executable, "-c", SOFTEST_MODE_BITS], env=environment, capture_output=True, text=True, check=True
        )
        answers.add(done.stdout)
    assert len(answers) == 1
