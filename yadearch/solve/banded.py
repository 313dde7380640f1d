"""Linear algebra on the arch's block-tridiagonal tangent (pure scipy): a block couples only with its
two neighbours, so with three degrees of freedom a block K is banded, five diagonals either side.
Banded solves, the stability test by a banded Cholesky factorisation and the softest mode by a
banded eigensolver cost a few per cent of their dense counterparts."""

from __future__ import annotations

import numpy as np
import scipy.linalg

BAND = 5  # diagonals either side of the main one: 3 degrees of freedom a block, neighbours only


def general(a: np.ndarray, shift: float = 0.0) -> np.ndarray:
    """`a` + shift I in LAPACK's general band storage (ab[BAND + i - j, j] = a[i, j])."""
    n = len(a)
    ab = np.zeros((2 * BAND + 1, n))
    for k in range(-min(BAND, n - 1), min(BAND, n - 1) + 1):
        ab[BAND - k, max(0, k): n + min(0, k)] = np.diagonal(a, k)
    ab[BAND] += shift
    return ab


def symmetric_upper(a: np.ndarray) -> np.ndarray:
    """The symmetric part of `a` in upper band storage (ab[BAND + i - j, j], i <= j)."""
    n = len(a)
    ab = np.zeros((BAND + 1, n))
    for k in range(min(BAND, n - 1) + 1):
        ab[BAND - k, k:] = 0.5 * (np.diagonal(a, k) + np.diagonal(a, -k))
    return ab


def solve(a: np.ndarray, b: np.ndarray, shift: float = 0.0) -> np.ndarray:
    """x with (a + shift I) x = b; LinAlgError if singular."""
    return scipy.linalg.solve_banded((BAND, BAND), general(a, shift), b, check_finite=False)


def positive_definite(a: np.ndarray) -> bool:
    """Whether the symmetric part of `a` is positive definite (its Cholesky factor exists)."""
    try:
        scipy.linalg.cholesky_banded(symmetric_upper(a), check_finite=False)
    except np.linalg.LinAlgError:
        return False
    return True


def smallest_eigenvalue(a: np.ndarray) -> float:
    """The smallest eigenvalue of the symmetric part of `a` (N/m for a stiffness): > 0 when stable."""
    values = scipy.linalg.eig_banded(symmetric_upper(a), eigvals_only=True, select="i", select_range=(0, 0),
                                     check_finite=False)
    return float(values[0])


def softest_mode(a: np.ndarray) -> np.ndarray:
    """The eigenvector of the smallest eigenvalue of the symmetric part of `a`."""
    _, vectors = scipy.linalg.eig_banded(symmetric_upper(a), select="i", select_range=(0, 0), check_finite=False)
    return vectors[:, 0]
