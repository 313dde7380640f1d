"""The compiled banded LU (solve.banded.band_solve) against LAPACK's through scipy: the same solution
(to round-off: bitwise on Debian's stack, within an ulp or two where PyPI's OpenBLAS orders its sums
otherwise), pivoting where the diagonal is small, singular matrices told, and the shift added to the
diagonal; the compiled Cholesky's verdict and the inverse iteration's smallest eigenvalue against
LAPACK's factorisation and eigensolver."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

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
    return 0.5 * (dense + dense.T)


@pytest.mark.parametrize("n", [3, 16, 159])
def test_the_stability_verdict_is_lapacks_cholesky(n):
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


@pytest.mark.parametrize("n", [3, 16, 159])
def test_the_smallest_eigenvalue_is_the_eigensolvers(n):
    """Stable matrices by inverse iteration, others by the eigensolver: the same value to round-off of the
    matrix's norm."""
    rng = np.random.default_rng(200 + n)
    iterated = 0
    for shift in (12.0, 0.0):  # positive definite (inverse iteration), then mostly indefinite
        for _ in range(10):
            dense = random_band(n, rng) + shift * np.eye(n)
            expected = np.linalg.eigvalsh(symmetric_part(dense))[0]
            found = banded.smallest_eigenvalue(banded.from_dense(dense))
            assert found == pytest.approx(expected, rel=1e-9, abs=1e-12 * np.abs(dense).max() * n)
            iterated += expected > 0.0
    assert iterated >= 10
